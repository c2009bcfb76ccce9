#!/usr/bin/python3
"""Paired A/B of two carrom_bench builds on a machine whose speed drifts.

Runs the old and the new benchmark binary at the same time, one pinned to each of CPUs 0 and 1,
then swapped, for a number of rounds, and reports per benchmark the median ratio new/old of
items_per_second. Both runs of a round see the same moment of the machine, so the minute-to-
minute drift of a shared virtual machine (up to 30 % here) largely cancels; giving the same
binary as --old and --new shows what is left (the ratio should be about 1).

Usage:
  scripts/bench_ab.py --old OLD/bench/carrom_bench --new build/release/bench/carrom_bench \\
      [--filter BotsGreedyStandard] [--rounds 24]
"""

import argparse
import json
import statistics
import subprocess
import sys


def start(binary, cpu, bench_filter):
    return subprocess.Popen(
        ["taskset", "-c", str(cpu), binary, f"--benchmark_filter={bench_filter}",
         "--benchmark_format=json"],
        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)


def rates(process):
    out, _ = process.communicate()
    if process.returncode != 0:
        sys.exit(f"bench_ab: a benchmark run failed (exit {process.returncode})")
    return {b["name"]: b["items_per_second"] for b in json.loads(out)["benchmarks"]
            if "items_per_second" in b}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--old", required=True, help="the reference carrom_bench")
    parser.add_argument("--new", required=True, help="the carrom_bench under test")
    parser.add_argument("--filter", default="BotsGreedyStandard", help="benchmark filter")
    parser.add_argument("--rounds", type=int, default=24, help="rounds (1-200)")
    args = parser.parse_args()
    if not 1 <= args.rounds <= 200:
        sys.exit("bench_ab: --rounds must be in [1, 200]")
    ratios, old_rates, new_rates = {}, {}, {}
    for r in range(args.rounds):
        old_cpu, new_cpu = (0, 1) if r % 2 == 0 else (1, 0)
        old_run = start(args.old, old_cpu, args.filter)
        new_run = start(args.new, new_cpu, args.filter)
        old, new = rates(old_run), rates(new_run)
        for name in old.keys() & new.keys():
            ratios.setdefault(name, []).append(new[name] / old[name])
            old_rates.setdefault(name, []).append(old[name])
            new_rates.setdefault(name, []).append(new[name])
    print("| benchmark | old median items/s | new median items/s | new/old median | new/old range |")
    print("| --- | --- | --- | --- | --- |")
    for name in sorted(ratios):
        v = ratios[name]
        print(f"| {name} | {statistics.median(old_rates[name]):,.0f} | "
              f"{statistics.median(new_rates[name]):,.0f} | {statistics.median(v):.3f} | "
              f"{min(v):.3f}-{max(v):.3f} |")


if __name__ == "__main__":
    main()
