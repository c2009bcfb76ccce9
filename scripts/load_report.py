#!/usr/bin/python3
"""Runs carrom-load at several match counts and writes the table and plot of docs/server-load.md.

usage: scripts/load_report.py --build build/release [--matches 10 100 250 500 1000]
                              [--duration 20] [--think-ms 8000] [--think-spread-ms 4000]
                              [--out-json /tmp/load.json] [--plot docs/img/server-load-human.png]

Each run starts its own carrom-server (Release build, 127.0.0.1, ephemeral port, 2 I/O threads),
ramps the matches up, measures for --duration seconds and stops the server. Prints a Markdown
table on stdout. Bounded: at most 5,000 matches per run and 600 s of measurement.
"""
import argparse
import json
import os
import subprocess
import sys


def run(build, matches, duration, think_ms, extra, nice):
    load = os.path.join(build, "bots", "carrom-load")
    server = os.path.join(build, "server", "carrom-server")
    ramp = max(2.0, matches / 100.0)
    cmd = [load, "--server-bin", server, "--matches", str(matches), "--ramp", str(ramp),
           "--warmup", "5", "--duration", str(duration), "--think-ms", str(think_ms)] + extra
    with open("/proc/loadavg") as f:
        loadavg = f.read().split()[0]
    preexec = None
    if nice:
        cmd = ["nice", "-n", str(nice)] + cmd

        def preexec():
            # With scheduler autogroups (kernel.sched_autogroup_enabled=1) a nice value counts
            # only inside its session: a new session whose autogroup gets the same nice value
            # makes it count against other sessions' work too.
            os.setsid()
            try:
                with open("/proc/self/autogroup", "w") as f:
                    f.write(str(nice))
            except OSError:
                pass
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=duration + ramp + 120,
                          preexec_fn=preexec)
    result = json.loads(proc.stdout)
    result["command"] = " ".join(cmd).replace(build + "/", "")
    result["loadavg_before"] = float(loadavg)
    result["exit"] = proc.returncode
    return result


def think_spread(row):
    spread = row.get("think_spread_ms", 0)
    return f" ± {spread}" if spread else ""


def table(rows):
    head = ("| matches | think ms | held | server CPU % | load tool CPU % | msgs/s received | "
            "snapshot lag p50 / p99 ms | relative lag p50 / p99 ms | server send lag p50 / p99 | "
            "snapshots dropped | "
            "KB/s per client while moving | KiB per match | load avg |")
    lines = [head, "|" + " --- |" * 13]
    for r in rows:
        lines.append(
            f"| {r['matches']} | {r['think_ms']}{think_spread(r)} | {r['held_at_end']} | "
            f"{r['server_cpu_percent']:.0f} | {r['client_cpu_percent']:.0f} | "
            f"{r['client_messages_per_s']:.0f} | {r['snapshot_lag_ms_p50']:.1f} / "
            f"{r['snapshot_lag_ms_p99']:.1f} | {r['relative_lag_ms_p50']:.1f} / "
            f"{r['relative_lag_ms_p99']:.1f} | {r['server_send_lag_p50']} / "
            f"{r['server_send_lag_p99']} | {r['snapshots_dropped']:.0f} | "
            f"{r['bytes_per_client_per_s_moving'] / 1000:.1f} | "
            f"{r['server_kib_per_match']:.0f} | {r['loadavg_before']:.1f} |")
    return "\n".join(lines)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = [r["matches"] for r in rows]
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(n, [r["snapshot_lag_ms_p50"] for r in rows], "o-", label="p50")
    ax[0].plot(n, [r["snapshot_lag_ms_p99"] for r in rows], "s-", label="p99")
    ax[0].axhline(5.0, color="grey", linestyle="--", label="target p99 5 ms")
    ax[0].set_xlabel("concurrent matches")
    ax[0].set_ylabel("snapshot lag behind the room's schedule, ms")
    ax[0].set_yscale("log")
    ax[0].legend()
    ax[1].plot(n, [r["server_cpu_percent"] for r in rows], "o-", label="server CPU %")
    ax[1].plot(n, [r["server_messages_out_per_s"] / 1000 for r in rows], "s-",
               label="messages out, thousands/s")
    ax[1].set_xlabel("concurrent matches")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True)
    parser.add_argument("--matches", type=int, nargs="+", default=[10, 100, 250, 500, 1000])
    parser.add_argument("--duration", type=float, default=20.0)
    parser.add_argument("--think-ms", type=int, default=0)
    parser.add_argument("--think-spread-ms", type=int, default=0,
                        help="each pause drawn uniformly within this of --think-ms")
    parser.add_argument("--server-arg", action="append", default=[])
    parser.add_argument("--nice", type=int, default=0,
                        help="run at this niceness, in a new session whose scheduler autogroup "
                             "gets the same niceness (negative, as root: less disturbed by other "
                             "work on the machine)")
    parser.add_argument("--out-json")
    parser.add_argument("--plot")
    args = parser.parse_args()
    extra = ["--think-spread-ms", str(args.think_spread_ms)] if args.think_spread_ms else []
    for a in args.server_arg:
        extra += ["--server-arg=" + a]
    rows = []
    for m in args.matches:
        if not 1 <= m <= 5000:
            sys.exit("matches must be in 1..5000")
        rows.append(run(args.build, m, args.duration, args.think_ms, extra, args.nice))
        print(json.dumps(rows[-1]), file=sys.stderr)
    if args.out_json:
        with open(args.out_json, "w") as f:
            json.dump(rows, f, indent=2)
    if args.plot:
        plot(rows, args.plot)
    print(table(rows))
    for r in rows:
        print(f"- {r['matches']} matches: `{r['command']}`")


if __name__ == "__main__":
    main()
