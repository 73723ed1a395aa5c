#!/usr/bin/env python3
"""The search against random sampling: reads a hunt suite's summary.csv written with
`strategies = ["anneal", "random"]` (experiments/hunt/vs-random.toml) and prints a markdown
table: per algorithm and objective, the worst ratio each strategy found per seed, the mean, and
on how many seeds the search found a strictly worse ratio.

    python3 scripts/hunt-vs-random.py results/hunt-vs-random [--verdicts]

"Clearly better" (the verdict column) means: strictly worse ratio on every seed, or on all but one
seed with the other a tie. Exit 2 on a missing or malformed summary.
"""
import csv
import sys
from collections import defaultdict
from pathlib import Path


def fail(msg):
    print(f"hunt-vs-random: {msg}", file=sys.stderr)
    sys.exit(2)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(args) != 1:
        fail("usage: hunt-vs-random.py DIR (a hunt suite's --out folder)")
    path = Path(args[0]) / "summary.csv"
    if not path.is_file():
        fail(f"{path}: not found")
    runs = defaultdict(lambda: {"anneal": {}, "random": {}})
    against = {}
    with path.open(newline="") as f:
        for line, row in enumerate(csv.DictReader(f), start=2):
            try:
                key = (row["algorithm"], row["objective"])
                ratio = float(row["worst_ratio"]) if row["worst_ratio"] else None
                runs[key][row["strategy"]][int(row["seed"])] = (ratio, row["worst_instance"])
                against[key] = row["against"]
            except (KeyError, ValueError) as e:
                fail(f"{path}:{line}: {e!r}: expected a hunt suite's summary with a strategy column")
    print("| algorithm (objective) | against | search, seeds | random sampling, seeds | "
          "search mean | random mean | search worse | clearly better |")
    print("|---|---|---|---|---|---|---|---|")
    clear = 0
    for (algo, objective), by in runs.items():
        seeds = sorted(set(by["anneal"]) & set(by["random"]))
        if not seeds:
            fail(f"{algo} {objective}: no seed has both strategies")
        a = [by["anneal"][s][0] for s in seeds]
        r = [by["random"][s][0] for s in seeds]
        if None in a or None in r:
            fail(f"{algo} {objective}: a hunt found no ratio")
        worse = sum(x > y + 1e-9 for x, y in zip(a, r))
        ties = sum(abs(x - y) <= 1e-9 for x, y in zip(a, r))
        is_clear = worse == len(seeds) or (worse == len(seeds) - 1 and ties == 1)
        clear += is_clear
        fmt = lambda v: " / ".join(f"{x:.3f}" for x in v)
        mean = lambda v: sum(v) / len(v)
        print(f"| {algo} ({objective}) | {against[(algo, objective)]} | {fmt(a)} | {fmt(r)} | "
              f"{mean(a):.3f} | {mean(r):.3f} | {worse} of {len(seeds)}"
              f"{f', {ties} tie' if ties == 1 else f', {ties} ties' if ties else ''} | "
              f"{'yes' if is_clear else 'no'} |")
    print(f"\nClearly better for {clear} of {len(runs)} algorithm/objective pairs.")


if __name__ == "__main__":
    main()
