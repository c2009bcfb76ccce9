#!/usr/bin/python3
"""The summary and verdicts of a scripts/soak.sh run (docs/server-load.md, "Soak").

usage: scripts/soak_summary.py --dir DIR --warmup-s 300 [--load-exit N] [--server-exit N]
                               [--command TEXT]

Reads DIR/samples.csv and DIR/load.json, prints a table per 5 minutes and the verdicts, writes
DIR/summary.json. Exit 0 only when every verdict holds:
- RSS growth after warm-up < 5 %: VmRSS of the last sample under load against the first sample
  at or after the warm-up;
- descriptors back to baseline: open fds after the load (every session closed) equal those
  before it;
- zero errors: no error or critical line in the server's log, no error message received and no
  broken connection in the load tool, no store error, both processes exited with 0.
"""
import argparse
import csv
import json
import os
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dir", required=True)
    ap.add_argument("--warmup-s", type=int, default=300)
    ap.add_argument("--load-exit", type=int, default=0)
    ap.add_argument("--server-exit", type=int, default=0)
    ap.add_argument("--command", default="")
    args = ap.parse_args()

    with open(os.path.join(args.dir, "samples.csv")) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            if k != "phase":
                r[k] = float(v) if v else 0.0
    before = [r for r in rows if r["phase"] == "before"]
    load = [r for r in rows if r["phase"] == "load"]
    after = [r for r in rows if r["phase"] == "after"]
    if not before or not load or not after:
        print("soak: incomplete samples", file=sys.stderr)
        return 1
    try:
        with open(os.path.join(args.dir, "load.json")) as f:
            final = json.load(f)
    except (OSError, ValueError):
        final = {}

    warm = next((r for r in load if r["t_s"] >= args.warmup_s), load[0])
    end = load[-1]
    growth = 100.0 * (end["rss_kib"] - warm["rss_kib"]) / warm["rss_kib"]
    fds_base = int(before[0]["fds"])
    fds_peak = int(max(r["fds"] for r in rows))
    fds_end = int(after[-1]["fds"])
    last = after[-1]
    errors = {
        "server_log_errors": int(last["log_errors"]),
        "load_errors_received": int(final.get("errors_received", end["load_errors_received"])),
        "load_client_failures": int(final.get("client_failures", end["load_failures"])),
        "store_errors": int(last["store_errors"]),
        "load_exit": args.load_exit,
        "server_exit": args.server_exit,
    }
    verdicts = {
        "rss_growth_below_5_percent": growth < 5.0,
        "fds_back_to_baseline": fds_end == fds_base,
        "zero_errors": all(v == 0 for v in errors.values()),
    }
    summary = {
        "command": args.command,
        "minutes": round(end["t_s"] / 60.0),
        "rss_kib_before": int(before[0]["rss_kib"]),
        "rss_kib_after_warmup": int(warm["rss_kib"]),
        "warmup_sample_s": int(warm["t_s"]),
        "rss_kib_end_of_load": int(end["rss_kib"]),
        "rss_kib_peak": int(max(r["rss_kib"] for r in load)),
        "rss_kib_after_load": int(last["rss_kib"]),
        "rss_growth_percent": round(growth, 2),
        "fds_baseline": fds_base,
        "fds_peak": fds_peak,
        "fds_end": fds_end,
        "matches_started": int(final.get("matches_started", end["load_matches_started"])),
        "matches_finished": int(final.get("matches_finished", end["load_matches_finished"])),
        "server_matches_finished": int(last["server_matches_finished"]),
        "server_log_warnings": int(last["log_warnings"]),
        "errors_by_code": final.get("errors_by_code", {}),
        "server_cpu_percent": final.get("server_cpu_percent"),
        "client_cpu_percent": final.get("client_cpu_percent"),
        "errors": errors,
        "verdicts": verdicts,
    }
    with open(os.path.join(args.dir, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
        f.write("\n")

    print("| minute | RSS KiB | open fds | matches finished | errors |")
    print("| --- | --- | --- | --- | --- |")
    for r in rows:
        minute = r["t_s"] / 60.0
        if r["phase"] == "load" and r is not end and (minute % 5 != 0 or minute == 0):
            continue
        label = {"before": "before", "after": "after"}.get(r["phase"], f"{minute:g}")
        errs = int(r["log_errors"] + r["load_errors_received"] + r["load_failures"]
                   + r["store_errors"])
        print(f"| {label} | {int(r['rss_kib']):,} | {int(r['fds'])} | "
              f"{int(r['load_matches_finished']):,} | {errs} |")
    print()
    print(f"RSS after warm-up ({summary['warmup_sample_s']} s) {summary['rss_kib_after_warmup']:,} "
          f"KiB, at the end of the load {summary['rss_kib_end_of_load']:,} KiB: "
          f"{growth:+.2f} % ({'ok' if verdicts['rss_growth_below_5_percent'] else 'FAIL'}, < 5 %)")
    print(f"open fds before {fds_base}, peak {fds_peak}, after {fds_end} "
          f"({'ok' if verdicts['fds_back_to_baseline'] else 'FAIL'}, back to baseline)")
    print(f"errors {errors} ({'ok' if verdicts['zero_errors'] else 'FAIL'}, zero)")
    print(f"matches started {summary['matches_started']:,}, finished "
          f"{summary['matches_finished']:,} (server: {summary['server_matches_finished']:,})")
    print(f"summary: {os.path.join(args.dir, 'summary.json')}")
    return 0 if all(verdicts.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
