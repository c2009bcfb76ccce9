#!/usr/bin/env python3
"""A bot and a desktop client across an impaired link: what players feel on bad networks
(docs/network.md).

    sudo /usr/bin/python3 scripts/network_report.py --server PATH/carrom-server
        --bot PATH/carrom-bot --client PATH/carrom-client --sim PATH/carrom-sim
        [--profiles lan,rtt100,...] [--json FILE] [--plot FILE]

For each profile it builds two network namespaces joined by a veth pair (the server at
10.78.0.1, the players at 10.78.0.2; both addresses exist only inside the namespaces), impairs
the link, and plays one game (freestyle to 150 points, one board, no shot clock) between a
carrom-bot (--strategy random, seed 1, creates the room and breaks) and carrom-client under
Xvfb (xvfb-run -a) with --autoplay medium and --frame-log, through tests/support/fault_proxy.py
running beside the players. Every process runs under `timeout` and everything is removed at the
end (also on Ctrl-C).

Impairments (all inside the namespaces):
  latency, jitter  the proxy delays each chunk by RTT/2 +- jitter/2 per direction, in order;
  loss             an nftables rule drops that share of the packets leaving each side of the
                   veth (`numgen random mod 100 < N drop`), both directions;
  cap              `tc qdisc tbf` on both ends of the veth;
  outage           the players' end of the veth goes down for the given seconds, 0.3 s after the
                   bot's second shot is sent (so a shot is moving), then up again.

Measured from the bot's --trace and the client's --frame-log (both CLOCK_MONOTONIC, shared by all
processes) and the server's journal of the game (GET /matches/ID) replayed by
`carrom-sim --frame-error`:
  first motion     the client's own strokes (shooter): from its release to the first frame that
                   draws the striker moving, ms and frames; the bot's strokes (opponent): from the
                   bot's shot leaving it to the client's first frame that draws it moving, ms;
  interpolation    error of the drawn positions against the exact trajectory, RMS and max, px;
  jumps, freezes   frames where a body moved more than 3x its exact displacement + 2 px; runs of
                   unchanged frames longer than 2 frame intervals while the stroke moves;
  final            strokes whose board drawn at rest equals the server's final keyframe;
  bytes/s          bytes the players' end received over the game, per client;
  longest wait     the longest wait between two snapshots of one shot at the bot, ms;
  gaps, resumes    snapshots the server dropped for a slow reader; seats resumed (bot, client);
  result           the bot and the client finished the game and agree on the score.
Targets (docs/network.md): the shooter sees motion in the first frame rendered after release;
the opponent within RTT/2 + 50 ms of the stroke reaching the server; interpolation error below
0.5 px RMS at rtt100 and below 2 px at rtt250loss2; no final-state mismatch.
Exit 0 when every profile's game finished with both players agreeing, 1 otherwise.
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
STRIKER_ID = 19
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


def first_motion(trace, frames):
    """ms (and frames) from each release to the client's first frame drawing that stroke moving.

    Shooter: the client's own `shoot` lines; the release happens while a frame is being made (its
    board was rendered before the input), so the first frame rendered after it is the next frame
    line: `frames` is 1 when the motion shows there. Opponent: the bot's `shoot` trace lines.
    A frame draws a stroke moving when its shot time belongs to that turn, t > 0 and the striker
    (id 19) is drawn. Bot strokes shot before the client's first frame are left out."""
    frame_lines = [l for l in frames if l["kind"] == "frame"]

    def first_moving(turn, after_ms):
        for i, f in enumerate(frame_lines):
            if f["ms"] >= after_ms and f["turn"] == turn and f["t"] > 0 and any(
                    b[0] == STRIKER_ID for b in f["bodies"]):
                return i, f
        return None, None

    shooter, shooter_frames, opponent = [], [], []
    for line in frames:
        if line["kind"] != "shoot":
            continue
        i, f = first_moving(line["turn"], line["ms"])
        if f is None:
            continue
        shooter.append(f["ms"] - line["ms"])
        release = next(j for j, g in enumerate(frame_lines) if g["ms"] >= line["ms"])
        shooter_frames.append(f["frame"] - frame_lines[release]["frame"])
    first_frame_ms = frame_lines[0]["ms"] if frame_lines else float("inf")
    for line in trace:
        # A stroke shot before the client drew its first frame (the break, while its window
        # opens) has no first motion to measure.
        if line["kind"] == "shoot" and line["ms"] >= first_frame_ms:
            _, f = first_moving(line["turn"], line["ms"])
            if f is not None:
                opponent.append(f["ms"] - line["ms"])
    return shooter, shooter_frames, opponent


def longest_freeze(lines):
    """Longest wait, ms, between two snapshots of one shot reaching the bot."""
    longest = 0.0
    previous = None
    for line in lines:
        if line["kind"] != "snapshot":
            continue
        if previous is not None and previous["turn"] == line["turn"] and not previous["keyframe"]:
            longest = max(longest, line["ms"] - previous["ms"])
        previous = line
    return longest


def client_resumes(frames):
    """Times the client's link went from reconnecting back into the room."""
    count, lost = 0, False
    for line in frames:
        if line["kind"] != "frame":
            continue
        if line.get("link") in ("reconnecting", "connecting", "greeting"):
            lost = True
        elif line.get("link") == "in_room" and lost:
            count, lost = count + 1, False
    return count


def fetch_journal(link, port, path):
    """The game's journal from the server's Match API (the bot named `creator` played it)."""
    base = f"http://{SERVER_IP}:{port}"
    listing = json.loads(run(*ns_exec(link.ns_server, "curl", "-sf",
                                      f"{base}/matches?player=creator&limit=1")).stdout)
    match_id = listing["matches"][0]["id"]
    journal = run(*ns_exec(link.ns_server, "curl", "-sf", f"{base}/matches/{match_id}")).stdout
    pathlib.Path(path).write_text(journal)
    return match_id


def percentile(values, p):
    if not values:
        return None
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(p / 100 * (len(ordered) - 1))))]


def frame_error(sim_bin, frames_path, journal_path):
    out = run(sim_bin, "--frame-error", str(frames_path), str(journal_path), check=False)
    if out.returncode != 0:
        raise RuntimeError("carrom-sim --frame-error: " + out.stderr.strip())
    return json.loads(out.stdout)


def stroke_errors(strokes):
    """RMS and max over the given strokes' samples."""
    samples = sum(s["samples"] for s in strokes)
    if not samples:
        return {"rms_px": None, "max_px": None, "samples": 0}
    sum_sq = sum(s["rms_px"] ** 2 * s["samples"] for s in strokes)
    return {"rms_px": (sum_sq / samples) ** 0.5, "max_px": max(s["max_px"] for s in strokes),
            "samples": samples}


def measure(profile, work, port, link, sim_bin, summary, client_code, elapsed, rx,
            outage_done):
    desc, rtt = PROFILES[profile][0], PROFILES[profile][1]
    trace = read_trace(work / f"{profile}.bot.trace")
    frames = read_trace(work / f"{profile}.client.frames")
    shooter, shooter_frames, opponent = first_motion(trace, frames)
    if link is not None:
        fetch_journal(link, port, work / f"{profile}.journal.json")
    errors = frame_error(sim_bin, work / f"{profile}.client.frames",
                         work / f"{profile}.journal.json")
    own_turns = {l["turn"] for l in frames if l["kind"] == "shoot"}
    strokes = errors["strokes"]
    try:
        final = json.loads((work / f"{profile}.client.final").read_text())
    except (json.JSONDecodeError, FileNotFoundError):
        final = {}
    agree = (client_code == 0 and summary.get("ok") and summary.get("games") == 1 and
             final.get("scores") == summary.get("scores"))
    checked = [s for s in strokes if s["final"] is not None]
    return {
        "profile": profile,
        "description": desc,
        "rtt_ms": rtt,
        "finished": bool(agree),
        "scores": summary.get("scores"),
        "client_scores": final.get("scores"),
        "failures": {k: v for k, v in (("bot", summary.get("failure")),
                                       ("client", None if client_code == 0 else
                                        f"exit {client_code}")) if v},
        "strokes": len(strokes),
        "client_strokes": len(shooter),
        "bot_strokes": len(opponent),
        "shooter_first_motion_ms": {"median": percentile(shooter, 50),
                                    "p95": percentile(shooter, 95), "max": max(shooter, default=None)},
        "shooter_first_motion_frames": {"max": max(shooter_frames, default=None),
                                        "within_one": sum(1 for n in shooter_frames if n <= 1)},
        "opponent_first_motion_ms": {"median": percentile(opponent, 50),
                                     "p95": percentile(opponent, 95), "max": max(opponent, default=None)},
        "interpolation": {
            "all": stroke_errors(strokes),
            "shooter": stroke_errors([s for s in strokes if s["turn"] in own_turns]),
            "opponent": stroke_errors([s for s in strokes if s["turn"] not in own_turns])},
        "frame_interval_ms": errors["frame_interval_ms"],
        "jumps": errors["jumps"],
        "freezes": errors["freezes"],
        "longest_drawn_freeze_ms": errors["longest_freeze_ms"],
        "finals_checked": len(checked),
        "finals_equal": sum(1 for s in checked if s["final"]["equal"]),
        "final_max_difference_px": max((s["final"]["max_difference_px"] for s in checked),
                                       default=None),
        "bytes_per_s_per_client": rx / max(elapsed, 1e-9) / 2,
        "longest_freeze_ms": longest_freeze(trace),
        "game_s": elapsed,
        "seq_gaps": summary.get("seq_gaps", 0),
        "resumes": {"bot": summary.get("resumes", 0), "client": client_resumes(frames)},
        "outage_ended_at_s": outage_done,
    }


def remeasure(old, work, sim_bin):
    """The result of a kept game measured again from its logs (traffic and game length kept)."""
    if "error" in old:
        return old
    profile = old["profile"]
    try:
        summary = json.loads((work / f"{profile}.bot.json").read_text())
    except (json.JSONDecodeError, FileNotFoundError):
        summary = {"ok": False, "failure": "no summary"}
    client_code = 0 if (work / f"{profile}.client.final").exists() else 1
    result = measure(profile, work, None, None, sim_bin, summary, client_code, old["game_s"], 0,
                     old["outage_ended_at_s"])
    result["bytes_per_s_per_client"] = old["bytes_per_s_per_client"]
    return result


def play(profile, bins, work, tag, limit):
    desc, rtt, jitter, loss, cap, outage = PROFILES[profile]
    link = Link(tag)
    procs = []
    try:
        if loss:
            link.add_loss(loss)
        if cap:
            link.add_cap(cap)
        server_out = work / f"{profile}.server.out"
        database = work / f"{profile}.db"
        for stale in work.glob(f"{profile}.db*"):
            stale.unlink()
        server = subprocess.Popen(
            ns_exec(link.ns_server, "timeout", str(limit), bins["server"], "--host", SERVER_IP,
                    "--port", "0", "--shot-clock", "0", "--data", str(database), "--log-level",
                    "warn"),
            stdout=open(server_out, "w"), stderr=open(work / f"{profile}.server.err", "w"))
        procs.append(server)
        port = wait_line(server_out, f"listening on {SERVER_IP}:", server,
                         time.monotonic() + 15)
        if port is None:
            raise RuntimeError("the server did not start: " +
                               (work / f"{profile}.server.err").read_text())
        port = port.strip()
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
        url = f"ws://127.0.0.1:{proxy_port.strip()}"
        bot_err = work / f"{profile}.bot.err"
        bot = subprocess.Popen(
            ns_exec(link.ns_players, "timeout", str(limit), bins["bot"], "--url", url, "--name",
                    "creator", "--create", "--rule-set", "freestyle", "--target-points", "150",
                    "--boards", "1", "--shot-clock", "0", "--seed", "1", "--trace",
                    str(work / f"{profile}.bot.trace"), "--strategy", "random", "--games", "1",
                    "--timeout", str(limit - 10), "--resume-for", "130", "--log-level", "warn"),
            stdout=open(work / f"{profile}.bot.json", "w"), stderr=open(bot_err, "w"))
        procs.append(bot)
        code = wait_line(bot_err, "room ", bot, time.monotonic() + 30)
        if code is None:
            raise RuntimeError("the bot got no room: " + bot_err.read_text())
        client = subprocess.Popen(
            ns_exec(link.ns_players, "timeout", str(limit), "xvfb-run", "-a",
                    "-s", "-screen 0 1024x1024x24", bins["client"], "--url", url,
                    "--name", "joiner", "--join", code.strip(), "--autoplay", "medium", "--mute",
                    "--frame-log", str(work / f"{profile}.client.frames"),
                    "--final-state", str(work / f"{profile}.client.final"),
                    "--timeout", str(limit - 10)),
            stdout=open(work / f"{profile}.client.out", "w"),
            stderr=open(work / f"{profile}.client.err", "w"))
        procs.append(client)
        start_rx = link.players_rx_bytes()
        start = time.monotonic()
        outage_done = None
        if outage:
            # The bot's second shot (turn 2 or later) with a moving board: 0.3 s after it.
            trace = work / f"{profile}.bot.trace"
            deadline = time.monotonic() + 90
            while time.monotonic() < deadline:
                if any(l["kind"] == "shoot" and l["turn"] >= 2 for l in read_trace(trace)):
                    break
                time.sleep(0.02)
            time.sleep(0.3)
            link.set_players_link(False)
            time.sleep(outage)
            link.set_players_link(True)
            outage_done = time.monotonic() - start
        bot.wait(timeout=limit)
        client_code = client.wait(timeout=limit)
        elapsed = time.monotonic() - start
        rx = link.players_rx_bytes() - start_rx
        try:
            summary = json.loads((work / f"{profile}.bot.json").read_text())
        except (json.JSONDecodeError, FileNotFoundError):
            summary = {"ok": False, "failure": "no summary"}
        return measure(profile, work, port, link, bins["sim"], summary, client_code, elapsed,
                       rx, outage_done)
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


# Interpolation error targets, px RMS (issue 23); other profiles have none.
RMS_TARGETS = {"rtt100": 0.5, "rtt250loss2": 2.0}


def targets(r):
    """Which targets hold: shooter, opponent, interpolation, final (None: no target)."""
    rtt = r["rtt_ms"]
    shooter = r["shooter_first_motion_frames"]
    opponent = r["opponent_first_motion_ms"]["max"]
    rms = r["interpolation"]["all"]["rms_px"]
    return {
        "shooter_within_one_frame": shooter["max"] is not None and shooter["max"] <= 1,
        # Both players sit behind the same proxy: the bot's stroke travels RTT/2 to the server
        # before the opponent's half of the path starts.
        "opponent_within_rtt_half_plus_50ms": opponent is not None and
        opponent - rtt / 2 <= rtt / 2 + 50,
        "interpolation_rms": None if r["profile"] not in RMS_TARGETS or rms is None else
        rms < RMS_TARGETS[r["profile"]],
        "final_state_equal": r["finals_checked"] > 0 and r["finals_equal"] == r["finals_checked"],
    }


def plot(results, path):
    """First motion (median, whisker to max), interpolation error and traffic per profile."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in results if "error" not in r]
    labels = [r["profile"] for r in rows]
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2), gridspec_kw={"width_ratios": [2, 1.4, 1]})
    x = range(len(rows))
    for offset, key, name, colour in ((-0.2, "shooter_first_motion_ms", "shooter (client)", "#4a7"),
                                      (0.2, "opponent_first_motion_ms", "opponent (client)", "#47a")):
        med = [r[key]["median"] or 0 for r in rows]
        top = [max(0, (r[key]["max"] or 0) - (r[key]["median"] or 0)) for r in rows]
        ax[0].bar([i + offset for i in x], med, width=0.4, yerr=[[0] * len(rows), top],
                  capsize=3, color=colour, label=f"{name} (median, whisker to max)")
    ax[0].set_xticks(list(x), labels, fontsize=8, rotation=30)
    ax[0].set_ylabel("ms from release to the first frame\ndrawing the striker moving")
    ax[0].set_yscale("symlog", linthresh=10)
    ax[0].legend(fontsize=8)
    ax[0].set_title("First drawn motion", fontsize=10)
    for offset, key, colour in ((-0.2, "rms_px", "#a47"), (0.2, "max_px", "#c88")):
        ax[1].bar([i + offset for i in x], [r["interpolation"]["all"][key] or 0 for r in rows],
                  width=0.4, color=colour, label=key.replace("_px", ""))
    ax[1].set_xticks(list(x), labels, fontsize=8, rotation=30)
    ax[1].set_yscale("symlog", linthresh=1)
    ax[1].set_ylabel("px, drawn against the exact trajectory")
    ax[1].legend(fontsize=8)
    ax[1].set_title("Interpolation error", fontsize=10)
    ax[2].bar(list(x), [r["bytes_per_s_per_client"] / 1000 for r in rows], color="#a74")
    ax[2].set_xticks(list(x), labels, fontsize=8, rotation=30)
    ax[2].set_ylabel("kB/s received per client (whole game)")
    ax[2].set_title("Traffic", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def fmt(value, digits=0):
    return "-" if value is None else f"{value:.{digits}f}"


def yes_no(value):
    return "-" if value is None else ("yes" if value else "NO")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--server", help="carrom-server binary")
    parser.add_argument("--bot", help="carrom-bot binary")
    parser.add_argument("--client", help="carrom-client binary")
    parser.add_argument("--sim", help="carrom-sim binary")
    parser.add_argument("--profiles", default=",".join(PROFILES),
                        help="comma-separated: " + ", ".join(PROFILES))
    parser.add_argument("--json", help="write the results here as well")
    parser.add_argument("--limit", type=int, default=400, help="seconds per profile, at most")
    parser.add_argument("--keep", help="keep the logs, traces, frame logs and journals here")
    parser.add_argument("--plot", help="draw the figures into this PNG (needs matplotlib)")
    parser.add_argument("--from-json", help="no games: print (and plot) these results")
    parser.add_argument("--remeasure", action="store_true",
                        help="with --from-json, --keep and --sim: measure the kept logs and "
                             "journals again (no games), write --json")
    args = parser.parse_args()
    if args.from_json and args.remeasure:
        results = [remeasure(r, pathlib.Path(args.keep), os.path.abspath(args.sim))
                   for r in json.loads(pathlib.Path(args.from_json).read_text())]
        if args.json:
            pathlib.Path(args.json).write_text(json.dumps(results, indent=2) + "\n")
        return report(results, args)
    if args.from_json:
        results = json.loads(pathlib.Path(args.from_json).read_text())
        return report(results, args)
    bins = {"server": args.server, "bot": args.bot, "client": args.client, "sim": args.sim}
    if not all(bins.values()):
        sys.exit("network_report: --server, --bot, --client and --sim are needed (or --from-json)")
    bins = {k: os.path.abspath(v) for k, v in bins.items()}
    if os.geteuid() != 0:
        sys.exit("network_report: needs root (network namespaces, nftables, tc)")
    profiles = [p for p in args.profiles.split(",") if p]
    unknown = [p for p in profiles if p not in PROFILES]
    if unknown:
        sys.exit(f"network_report: unknown profile(s) {', '.join(unknown)}")
    needs = {"ip": "iproute2", "tc": "iproute2", "curl": "curl", "xvfb-run": "xvfb"}
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
                results.append(play(profile, bins, work, f"{os.getpid() % 10000}{i}", args.limit))
            except (RuntimeError, subprocess.CalledProcessError, KeyError, IndexError,
                    json.JSONDecodeError) as error:
                detail = getattr(error, "stderr", "") or ""
                results.append({"profile": profile, "description": PROFILES[profile][0],
                                "finished": False, "error": f"{error} {detail}".strip()})
            if args.json:
                pathlib.Path(args.json).write_text(json.dumps(results, indent=2) + "\n")
    return report(results, args)


def report(results, args):
    print("| profile | finished, same score | strokes (client / bot) | shooter first motion: "
          "median / max ms, max frames | opponent: median / max ms | interpolation RMS / max px "
          "| jumps | drawn freezes, longest ms | final drawn = server | bytes/s per client "
          "| longest snapshot wait, ms | resumes (bot / client) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in results:
        if "error" in r:
            print(f"| {r['description']} | no: {r['error']} | | | | | | | | | | |")
            continue
        s, o = r["shooter_first_motion_ms"], r["opponent_first_motion_ms"]
        e = r["interpolation"]["all"]
        print(f"| {r['description']} | {'yes' if r['finished'] else 'NO'} | "
              f"{r['client_strokes']} / {r['bot_strokes']} | "
              f"{fmt(s['median'], 1)} / {fmt(s['max'], 1)}, "
              f"{fmt(r['shooter_first_motion_frames']['max'])} | "
              f"{fmt(o['median'])} / {fmt(o['max'])} | {fmt(e['rms_px'], 3)} / {fmt(e['max_px'], 2)} | "
              f"{r['jumps']} | {r['freezes']}, {fmt(r['longest_drawn_freeze_ms'])} | "
              f"{r['finals_equal']} of {r['finals_checked']} | "
              f"{fmt(r['bytes_per_s_per_client'])} | {fmt(r.get('longest_freeze_ms'))} | "
              f"{r['resumes']['bot']} / {r['resumes']['client']} |")
    print()
    print("| profile | shooter within one frame | opponent within RTT/2 + 50 ms | "
          "interpolation RMS target | final state equal |")
    print("| --- | --- | --- | --- | --- |")
    for r in results:
        if "error" in r:
            continue
        t = targets(r)
        print(f"| {r['profile']} | {yes_no(t['shooter_within_one_frame'])} | "
              f"{yes_no(t['opponent_within_rtt_half_plus_50ms'])} | "
              f"{yes_no(t['interpolation_rms'])} | {yes_no(t['final_state_equal'])} |")
    if args.plot:
        plot(results, args.plot)
    return 0 if all(r.get("finished") for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
