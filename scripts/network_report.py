#!/usr/bin/env python3
"""Bot matches across an impaired link: what players feel on bad networks (docs/network.md).

    sudo scripts/network_report.py --server PATH/carrom-server --bot PATH/carrom-bot
                                   [--profiles lan,rtt100,...] [--json FILE]

For each profile it builds two network namespaces joined by a veth pair (the server at
10.78.0.1, the players at 10.78.0.2; both addresses exist only inside the namespaces), impairs
the link, and plays one match of two carrom-bots (two games of freestyle to 60 points, random shots, one board) through
tests/support/fault_proxy.py running beside the players. Every process runs under `timeout`
and everything is removed at the end (also on Ctrl-C).

Impairments (all inside the namespaces):
  latency, jitter  the proxy delays each chunk by RTT/2 +- jitter/2 per direction, in order;
  loss             an nftables rule drops that share of the packets leaving each side of the
                   veth (`numgen random mod 100 < N drop`), both directions;
  cap              `tc qdisc tbf` on both ends of the veth;
  outage           the players' end of the veth goes down for the given seconds, 0.3 s after a
                   shot is sent (so a shot is moving), then up again.

Measured from the bots' --trace files (CLOCK_MONOTONIC, shared by all processes):
  first motion     from a shot leaving the shooter to the first snapshot of that turn reaching
                   the shooter, and the opponent: median and 95th percentile, ms;
  bytes/s          bytes the players' end received over the match, per client;
  longest freeze   the longest wait between two snapshots of one shot at either bot, ms;
  gaps, resumes    snapshots the server dropped for a slow reader; seats resumed;
  result           both bots finished the match and agree on the score.
Exit 0 when every profile's match finished with both bots agreeing, 1 otherwise.
"""
import argparse
import json
import os
import pathlib
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

SOURCE = pathlib.Path(__file__).resolve().parent.parent
PROXY = SOURCE / "tests" / "support" / "fault_proxy.py"
SUBNET = "10.78.0"
SERVER_IP = f"{SUBNET}.1"
PLAYERS_IP = f"{SUBNET}.2"

# name: (description, rtt ms, jitter ms, loss %, cap kbit/s, outage s)
PROFILES = {
    "lan": ("LAN (no impairment)", 0, 0, 0, 0, 0),
    "rtt100": ("100 ms RTT, 20 ms jitter", 100, 20, 0, 0, 0),
    "rtt250loss2": ("250 ms RTT, 50 ms jitter, 2 % loss", 250, 50, 2, 0, 0),
    "cap500k": ("500 kbit/s cap", 0, 0, 0, 500, 0),
    "outage3": ("3 s outage during a shot", 0, 0, 0, 0, 3),
    "outage75": ("75 s outage during a shot (longer than the idle timeout)", 0, 0, 0, 0, 75),
}


def run(*args, check=True, **kw):
    return subprocess.run(list(args), check=check, capture_output=True, text=True, **kw)


def ns_exec(ns, *args):
    return ["ip", "netns", "exec", ns, *args]


class Link:
    """Two namespaces and a veth pair; removed by close()."""

    def __init__(self, tag):
        self.ns_server = f"carrom-nr-srv-{tag}"
        self.ns_players = f"carrom-nr-ply-{tag}"
        self.veth_server = f"nrs{tag}"
        self.veth_players = f"nrp{tag}"
        run("ip", "netns", "add", self.ns_server)
        run("ip", "netns", "add", self.ns_players)
        run("ip", "link", "add", self.veth_server, "type", "veth", "peer", "name",
            self.veth_players)
        run("ip", "link", "set", self.veth_server, "netns", self.ns_server)
        run("ip", "link", "set", self.veth_players, "netns", self.ns_players)
        run("ip", "-n", self.ns_server, "addr", "add", f"{SERVER_IP}/30", "dev", self.veth_server)
        run("ip", "-n", self.ns_players, "addr", "add", f"{PLAYERS_IP}/30", "dev",
            self.veth_players)
        for ns, dev in ((self.ns_server, self.veth_server), (self.ns_players, self.veth_players)):
            run("ip", "-n", ns, "link", "set", "lo", "up")
            run("ip", "-n", ns, "link", "set", dev, "up")

    def ends(self):
        return ((self.ns_server, self.veth_server), (self.ns_players, self.veth_players))

    def add_loss(self, percent):
        for ns, dev in self.ends():
            rules = (f'table inet carrom_loss {{\n chain out {{\n'
                     f'  type filter hook output priority 0;\n'
                     f'  oifname "{dev}" numgen random mod 100 < {percent} drop\n }}\n}}\n')
            subprocess.run(ns_exec(ns, "nft", "-f", "-"), input=rules, text=True, check=True,
                           capture_output=True)

    def add_cap(self, kbit):
        for ns, dev in self.ends():
            run(*ns_exec(ns, "tc", "qdisc", "add", "dev", dev, "root", "tbf", "rate",
                         f"{kbit}kbit", "burst", "16kbit", "latency", "400ms"))

    def set_players_link(self, up):
        run("ip", "-n", self.ns_players, "link", "set", self.veth_players, "up" if up else "down")

    def players_rx_bytes(self):
        out = run(*ns_exec(self.ns_players, "cat",
                           f"/sys/class/net/{self.veth_players}/statistics/rx_bytes"))
        return int(out.stdout.strip())

    def close(self):
        for ns in (self.ns_players, self.ns_server):
            pids = run("ip", "netns", "pids", ns, check=False).stdout.split()
            for pid in pids:
                try:
                    os.kill(int(pid), signal.SIGKILL)
                except (ProcessLookupError, ValueError):
                    pass
        run("ip", "-n", self.ns_server, "link", "del", self.veth_server, check=False)
        run("ip", "netns", "del", self.ns_players, check=False)
        run("ip", "netns", "del", self.ns_server, check=False)


def wait_line(path, prefix, proc, deadline):
    """The first line of the file at path that starts with prefix (rest of it), or None."""
    while time.monotonic() < deadline:
        try:
            for line in pathlib.Path(path).read_text().splitlines():
                if line.startswith(prefix):
                    return line[len(prefix):]
        except FileNotFoundError:
            pass
        if proc.poll() is not None:
            return None
        time.sleep(0.05)
    return None


def read_trace(path):
    lines = []
    try:
        for line in pathlib.Path(path).read_text().splitlines():
            try:
                lines.append(json.loads(line))
            except json.JSONDecodeError:
                pass
    except FileNotFoundError:
        pass
    return lines


def first_motion(traces):
    """Per shot: ms from the shot leaving its bot to each bot's first snapshot of that turn."""
    shots = {}  # turn -> (shooter name, ms)
    for name, lines in traces.items():
        for line in lines:
            if line["kind"] == "shoot":
                shots.setdefault(line["turn"], (name, line["ms"]))
    shooter_ms, opponent_ms = [], []
    for turn, (shooter, sent) in shots.items():
        for name, lines in traces.items():
            arrivals = [l["ms"] for l in lines if l["kind"] == "snapshot" and l["turn"] == turn
                        and not l["keyframe"] and l["ms"] >= sent]
            if arrivals:
                (shooter_ms if name == shooter else opponent_ms).append(arrivals[0] - sent)
    return shooter_ms, opponent_ms


def longest_freeze(traces):
    """Longest wait, ms, between two snapshots of one shot reaching a bot (the picture froze)."""
    longest = 0.0
    for lines in traces.values():
        previous = None
        for line in lines:
            if line["kind"] != "snapshot":
                continue
            if previous is not None and previous["turn"] == line["turn"] and not previous["keyframe"]:
                longest = max(longest, line["ms"] - previous["ms"])
            previous = line
    return longest


def percentile(values, p):
    if not values:
        return None
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(p / 100 * (len(ordered) - 1))))]


def play(profile, server_bin, bot_bin, work, tag, limit):
    desc, rtt, jitter, loss, cap, outage = PROFILES[profile]
    link = Link(tag)
    procs = []
    try:
        if loss:
            link.add_loss(loss)
        if cap:
            link.add_cap(cap)
        server_out = work / f"{profile}.server.out"
        server = subprocess.Popen(
            ns_exec(link.ns_server, "timeout", str(limit), server_bin, "--host", SERVER_IP,
                    "--port", "0", "--shot-clock", "0", "--data", "none", "--log-level", "warn"),
            stdout=open(server_out, "w"), stderr=open(work / f"{profile}.server.err", "w"))
        procs.append(server)
        port = wait_line(server_out, f"listening on {SERVER_IP}:", server,
                         time.monotonic() + 15)
        if port is None:
            raise RuntimeError("the server did not start: " +
                               (work / f"{profile}.server.err").read_text())
        proxy_out = work / f"{profile}.proxy.out"
        proxy = subprocess.Popen(
            ns_exec(link.ns_players, "timeout", str(limit), sys.executable, str(PROXY),
                    "--target", f"{SERVER_IP}:{port}", "--control", str(work / "control"),
                    "--delay-ms", str(rtt / 2), "--jitter-ms", str(jitter / 2), "--seed", "7"),
            stdout=open(proxy_out, "w"), stderr=open(work / f"{profile}.proxy.err", "w"))
        procs.append(proxy)
        proxy_port = wait_line(proxy_out, "listening on 127.0.0.1:", proxy,
                               time.monotonic() + 15)
        if proxy_port is None:
            raise RuntimeError("the proxy did not start")
        url = f"ws://127.0.0.1:{proxy_port}"
        common = ["--strategy", "random", "--games", "2", "--timeout", str(limit - 10), "--resume-for", "130",
                  "--log-level", "warn"]
        bots = {}
        creator_err = work / f"{profile}.creator.err"
        bots["creator"] = subprocess.Popen(
            ns_exec(link.ns_players, "timeout", str(limit), bot_bin, "--url", url, "--name",
                    "creator", "--create", "--rule-set", "freestyle", "--target-points", "60",
                    "--boards", "1", "--shot-clock", "0", "--seed", "1", "--trace",
                    str(work / f"{profile}.creator.trace"), *common),
            stdout=open(work / f"{profile}.creator.json", "w"), stderr=open(creator_err, "w"))
        procs.extend(bots.values())
        code = wait_line(creator_err, "room ", bots["creator"], time.monotonic() + 30)
        if code is None:
            raise RuntimeError("the first bot got no room: " + creator_err.read_text())
        bots["joiner"] = subprocess.Popen(
            ns_exec(link.ns_players, "timeout", str(limit), bot_bin, "--url", url, "--name",
                    "joiner", "--join", code.strip(), "--seed", "2", "--trace",
                    str(work / f"{profile}.joiner.trace"), *common),
            stdout=open(work / f"{profile}.joiner.json", "w"),
            stderr=open(work / f"{profile}.joiner.err", "w"))
        procs.append(bots["joiner"])
        start_rx = link.players_rx_bytes()
        start = time.monotonic()
        outage_done = None
        if outage:
            # The first shot of the joiner (turn 1 or later) with a moving board: 0.3 s after it.
            trace = work / f"{profile}.creator.trace"
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline:
                if any(l["kind"] == "shoot" and l["turn"] >= 2 for l in read_trace(trace)):
                    break
                time.sleep(0.02)
            time.sleep(0.3)
            link.set_players_link(False)
            time.sleep(outage)
            link.set_players_link(True)
            outage_done = time.monotonic() - start
        for bot in bots.values():
            bot.wait(timeout=limit)
        elapsed = time.monotonic() - start
        rx = link.players_rx_bytes() - start_rx
        summaries = {}
        for name in bots:
            try:
                summaries[name] = json.loads((work / f"{profile}.{name}.json").read_text())
            except (json.JSONDecodeError, FileNotFoundError):
                summaries[name] = {"ok": False, "failure": "no summary"}
        traces = {name: read_trace(work / f"{profile}.{name}.trace") for name in bots}
        shooter, opponent = first_motion(traces)
        agree = (all(s.get("ok") and s.get("games") == 2 for s in summaries.values()) and
                 summaries["creator"].get("scores") == summaries["joiner"].get("scores"))
        return {
            "profile": profile,
            "description": desc,
            "finished": agree,
            "scores": summaries["creator"].get("scores"),
            "failures": {n: s.get("failure") for n, s in summaries.items() if s.get("failure")},
            "shots": len(shooter),
            "shooter_first_motion_ms": {"median": percentile(shooter, 50),
                                        "p95": percentile(shooter, 95)},
            "opponent_first_motion_ms": {"median": percentile(opponent, 50),
                                         "p95": percentile(opponent, 95)},
            "bytes_per_s_per_client": rx / max(elapsed, 1e-9) / 2,
            "longest_freeze_ms": longest_freeze(traces),
            "match_s": elapsed,
            "seq_gaps": sum(s.get("seq_gaps", 0) for s in summaries.values()),
            "resumes": {n: s.get("resumes", 0) for n, s in summaries.items()},
            "outage_ended_at_s": outage_done,
        }
    finally:
        for p in procs:
            if p.poll() is None:
                p.kill()
        for p in procs:
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                pass
        link.close()


def plot(results, path):
    """First motion (median, p95 whiskers) for shooter and opponent, and bytes/s, per profile."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in results if "error" not in r]
    labels = [r["profile"] for r in rows]
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2), gridspec_kw={"width_ratios": [2, 1, 1]})
    x = range(len(rows))
    for offset, key, name, colour in ((-0.2, "shooter_first_motion_ms", "shooter", "#4a7"),
                                      (0.2, "opponent_first_motion_ms", "opponent", "#47a")):
        med = [r[key]["median"] or 0 for r in rows]
        p95 = [max(0, (r[key]["p95"] or 0) - (r[key]["median"] or 0)) for r in rows]
        ax[0].bar([i + offset for i in x], med, width=0.4, yerr=[[0] * len(rows), p95],
                  capsize=3, color=colour, label=f"{name} (median, whisker to p95)")
    ax[0].set_xticks(list(x), labels, fontsize=8, rotation=30)
    ax[0].set_ylabel("ms from the shot leaving the shooter\nto its first snapshot")
    ax[0].set_yscale("symlog", linthresh=10)
    ax[0].legend(fontsize=8)
    ax[0].set_title("First motion", fontsize=10)
    ax[1].bar(list(x), [r.get("longest_freeze_ms", 0) for r in rows], color="#a47")
    ax[1].set_xticks(list(x), labels, fontsize=8, rotation=30)
    ax[1].set_yscale("symlog", linthresh=10)
    ax[1].set_ylabel("ms between two snapshots of a shot")
    ax[1].set_title("Longest freeze", fontsize=10)
    ax[2].bar(list(x), [r["bytes_per_s_per_client"] / 1000 for r in rows], color="#a74")
    ax[2].set_xticks(list(x), labels, fontsize=8, rotation=30)
    ax[2].set_ylabel("kB/s received per client (whole match)")
    ax[2].set_title("Traffic", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def fmt(value, digits=0):
    return "-" if value is None else f"{value:.{digits}f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--server", help="carrom-server binary")
    parser.add_argument("--bot", help="carrom-bot binary")
    parser.add_argument("--profiles", default=",".join(PROFILES),
                        help="comma-separated: " + ", ".join(PROFILES))
    parser.add_argument("--json", help="write the results here as well")
    parser.add_argument("--limit", type=int, default=400, help="seconds per profile, at most")
    parser.add_argument("--keep", help="keep the logs and traces in this directory")
    parser.add_argument("--plot", help="draw the figures into this PNG (needs matplotlib)")
    parser.add_argument("--from-json", help="no matches: print (and plot) these results")
    args = parser.parse_args()
    if args.from_json:
        results = json.loads(pathlib.Path(args.from_json).read_text())
        return report(results, args)
    if not args.server or not args.bot:
        sys.exit("network_report: --server and --bot are needed (or --from-json)")
    if os.geteuid() != 0:
        sys.exit("network_report: needs root (network namespaces, nftables, tc)")
    profiles = [p for p in args.profiles.split(",") if p]
    unknown = [p for p in profiles if p not in PROFILES]
    if unknown:
        sys.exit(f"network_report: unknown profile(s) {', '.join(unknown)}")
    needs = {"ip": "iproute2", "tc": "iproute2"}
    if any(PROFILES[p][3] for p in profiles):
        needs["nft"] = "nftables"
    missing = sorted({pkg for tool, pkg in needs.items() if shutil.which(tool) is None})
    if missing:
        sys.exit(f"network_report: install {' '.join(missing)} first (apt-get install)")
    results = []
    with tempfile.TemporaryDirectory(prefix="carrom-netreport-") as tmp:
        work = pathlib.Path(args.keep or tmp)
        work.mkdir(parents=True, exist_ok=True)
        for i, profile in enumerate(profiles):
            print(f"network_report: {profile}: {PROFILES[profile][0]} ...", file=sys.stderr,
                  flush=True)
            try:
                results.append(play(profile, os.path.abspath(args.server),
                                    os.path.abspath(args.bot), work, f"{os.getpid() % 10000}{i}",
                                    args.limit))
            except (RuntimeError, subprocess.CalledProcessError) as error:
                detail = getattr(error, "stderr", "") or ""
                results.append({"profile": profile, "description": PROFILES[profile][0],
                                "finished": False, "error": f"{error} {detail}".strip()})
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(results, indent=2) + "\n")
    return report(results, args)


def report(results, args):
    print("| profile | finished, same score | shots | first motion, shooter: median / p95 ms "
          "| opponent: median / p95 ms | longest freeze, ms | bytes/s per client "
          "| dropped snapshots | resumes |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in results:
        if "error" in r:
            print(f"| {r['description']} | no: {r['error']} | | | | | | | |")
            continue
        s, o = r["shooter_first_motion_ms"], r["opponent_first_motion_ms"]
        print(f"| {r['description']} | {'yes' if r['finished'] else 'NO'} | {r['shots']} | "
              f"{fmt(s['median'])} / {fmt(s['p95'])} | {fmt(o['median'])} / {fmt(o['p95'])} | "
              f"{fmt(r.get('longest_freeze_ms'))} | "
              f"{fmt(r['bytes_per_s_per_client'])} | {r['seq_gaps']} | "
              f"{sum(r['resumes'].values())} |")
    if args.plot:
        plot(results, args.plot)
    return 0 if all(r.get("finished") for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
