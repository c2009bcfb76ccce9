#!/usr/bin/python3
"""Plots carrom-load's per-second timeline (lag_by_second) of one or more runs.

usage: scripts/load_timeline.py --json A.json [B.json ...] --label "8 s" ["8 s ± 4 s" ...]
                                --out docs/img/server-load-timeline.png

Each JSON file is one carrom-load result. The top panel shows delta snapshots received per second
of the window, the bottom one the p99 and the maximum of their lag behind the room's schedule in
that second, so a stall or a wave of shots shows where it happened.
"""
import argparse
import json
import statistics
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--json", nargs="+", required=True)
    parser.add_argument("--label", nargs="+", required=True)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    if len(args.json) != len(args.label):
        sys.exit("load_timeline: give one --label per --json")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
    for path, label in zip(args.json, args.label):
        with open(path) as f:
            rows = json.load(f)["lag_by_second"]
        typical = statistics.median(r[1] for r in rows)
        rows = [r for r in rows if r[1] >= typical / 4]  # drop a partial last second
        seconds = [r[0] for r in rows]
        line, = ax[0].plot(seconds, [r[1] / 1000 for r in rows], label=label)
        ax[1].plot(seconds, [r[2] for r in rows], color=line.get_color(), label=f"{label}: p99")
        ax[1].plot(seconds, [r[3] for r in rows], color=line.get_color(), linestyle=":",
                   label=f"{label}: max")
    ax[0].set_ylabel("delta snapshots / s, thousands")
    ax[0].legend()
    ax[1].axhline(5.0, color="grey", linestyle="--", label="target p99 5 ms")
    ax[1].set_yscale("log")
    ax[1].set_ylabel("lag behind schedule, ms")
    ax[1].set_xlabel("second of the measured window")
    ax[1].legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)


if __name__ == "__main__":
    main()
