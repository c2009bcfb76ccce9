#!/usr/bin/python3
"""Runs carrom-arena for the bot measurements of docs/bots.md and writes docs/bots-report.md
and docs/img/bots-strength.png.

usage: /usr/bin/python3 scripts/bots_report.py --arena build/release/bots/carrom-arena
           [--games 200] [--level-games 50] [--jobs 2] [--out docs/bots-report.md]

Every search is limited by candidates (--candidates 6000, more than a decision of the default
greedy search ever simulates, with a 60 s time budget), so the games are the same on any machine
and load: only the wall times differ. The default bot (300 ms budget) plays the same shots as
long as its decisions finish within 300 ms.
"""
import argparse
import json
import os
import subprocess
import time

RULE_SETS = ["icf", "seed", "freestyle", "discpool"]
LEVELS = ["random", "greedy:easy", "greedy:medium", "greedy:hard"]
PAIRS = [("greedy:hard", "random"), ("greedy:hard", "greedy:easy"),
         ("greedy:hard", "greedy:medium"), ("greedy:medium", "greedy:easy"),
         ("greedy:easy", "random")]


def arena(path, a, b, rule_set, games, jobs, seed=1):
    cmd = [path, "--a", a, "--b", b, "--rule-set", rule_set, "--games", str(games),
           "--jobs", str(jobs), "--candidates", "6000", "--think-ms", "60000",
           "--seed", str(seed)]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    result = json.loads(out)
    result["command"] = "carrom-arena " + " ".join(cmd[1:])
    return result


def name(spec):
    return spec.replace("greedy:", "")


def pair_table(rows):
    lines = ["| A | B | rule set | games | A wins | B wins | draws | A win rate (95 % interval) "
             "| strokes per game | A pocketed / stroke | B pocketed / stroke | A fouls / stroke |",
             "|" + " --- |" * 12]
    for r in rows:
        lo, hi = r["a_win_rate_95"]
        lines.append(
            f"| {name(r['a'])} | {name(r['b'])} | {r['rule_set']} | {r['games']} | {r['a_wins']} "
            f"| {r['b_wins']} | {r['draws'] + r['unfinished']} | {100 * r['a_win_rate']:.1f} % "
            f"({100 * lo:.1f}-{100 * hi:.1f}) | {r['strokes_per_game']:.1f} "
            f"| {r['a_side']['pocketed_per_stroke']:.2f} | {r['b_side']['pocketed_per_stroke']:.2f} "
            f"| {r['a_side']['fouls_per_stroke']:.3f} |")
    return "\n".join(lines)


def level_table(rows):
    lines = ["| level (self-play) | " + " | ".join(RULE_SETS) + " |",
             "|" + " --- |" * (len(RULE_SETS) + 1)]
    for level in LEVELS:
        cells = []
        for rule_set in RULE_SETS:
            r = rows[(level, rule_set)]
            cells.append(f"{r['strokes_per_game']:.1f} ({r['boards_per_game']:.1f} boards)")
        lines.append(f"| {name(level)} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def plot(pairs, levels, path, games):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    icf = [r for r in pairs if r["rule_set"] == "icf"]
    labels = [f"{name(r['a'])}\nvs {name(r['b'])}" for r in icf]
    rates = [100 * r["a_win_rate"] for r in icf]
    err_lo = [max(0.0, 100 * (r["a_win_rate"] - r["a_win_rate_95"][0])) for r in icf]
    err_hi = [max(0.0, 100 * (r["a_win_rate_95"][1] - r["a_win_rate"])) for r in icf]
    ax[0].bar(range(len(icf)), rates, yerr=[err_lo, err_hi], capsize=4, color="#4a7")
    ax[0].axhline(95, color="#c44", ls="--", lw=1, label="95 % (hard vs random target)")
    ax[0].axhline(70, color="#c84", ls=":", lw=1, label="70 % (hard vs easy target)")
    ax[0].set_xticks(range(len(icf)), labels, fontsize=8)
    ax[0].set_ylabel("A's win rate, % (95 % interval)")
    ax[0].set_ylim(0, 105)
    ax[0].set_title(f"icf, {games} games per pair")
    ax[0].legend(fontsize=7, loc="lower left")
    width = 0.2
    for i, level in enumerate(LEVELS):
        ax[1].bar([j + (i - 1.5) * width for j in range(len(RULE_SETS))],
                  [levels[(level, rs)]["strokes_per_game"] for rs in RULE_SETS], width,
                  label=name(level))
    ax[1].set_xticks(range(len(RULE_SETS)), RULE_SETS)
    ax[1].set_yscale("log")
    ax[1].set_ylabel("strokes per game (self-play, log)")
    ax[1].set_title("game length by level")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--arena", required=True)
    p.add_argument("--games", type=int, default=200)
    p.add_argument("--level-games", type=int, default=50)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--out", default="docs/bots-report.md")
    p.add_argument("--plot", default="docs/img/bots-strength.png")
    args = p.parse_args()
    started = time.time()
    pairs = [arena(args.arena, a, b, "icf", args.games, args.jobs) for a, b in PAIRS]
    for rule_set in RULE_SETS[1:]:
        for a, b in PAIRS[:2]:
            pairs.append(arena(args.arena, a, b, rule_set, args.games, args.jobs))
    levels = {(level, rs): arena(args.arena, level, level, rs, args.level_games, args.jobs)
              for level in LEVELS for rs in RULE_SETS}
    with open("/proc/loadavg") as f:
        loadavg = f.read().split()[0]
    plot(pairs, levels, args.plot, args.games)
    rel_plot = os.path.relpath(args.plot, os.path.dirname(args.out))
    text = f"""# Bot strength report

Generated by `/usr/bin/python3 scripts/bots_report.py --arena <build>/bots/carrom-arena
--games {args.games} --level-games {args.level_games} --jobs {args.jobs}` in
{time.time() - started:.0f} s (load average at the end {loadavg}). Each row is one
`carrom-arena` run; the command of every row is in the JSON below the tables. Games alternate
who breaks; searches are limited by candidates (not time), so every figure here except the
times is reproducible exactly.

![win rates and game lengths]({rel_plot})

## Win rates

{pair_table(pairs)}

## Strokes per game for each level in each rule set

Self-play ({args.level_games} games each): both seats at the same level; strokes by both players.

{level_table(levels)}

## Raw results

One `carrom-arena` JSON object per line (pairs, then self-play):

```json
{chr(10).join(json.dumps(r, separators=(",", ":")) for r in pairs + list(levels.values()))}
```
"""
    with open(args.out, "w") as f:
        f.write(text)
    print(pair_table(pairs))
    print(level_table(levels))


if __name__ == "__main__":
    main()
