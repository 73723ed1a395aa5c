#!/usr/bin/env python3
"""Every algorithm of a bench run beside the best known value of each instance and objective.

The best known value is the least value of any checker-valid row (the exact solver's walk at
its limit, or any algorithm's walk); `opt` marks instances whose optimum the exact solver
proved. Prints, per objective and instance group (small random regions with proven optima,
eroded regions by size), the median and worst ratio to the best known value, how many rows are
within 1.03 and 1.05 of it, and the median seconds per run (a run computes all of an
algorithm's objectives).

    scripts/lp-lns-table.py RUN_DIR
"""
import csv
import statistics
import sys
from collections import defaultdict

OBJECTIVES = ["cc-turns", "turns", "weighted-cc-c50", "weighted-c50"]


def group(r):
    if r["family"] == "eroded":
        style = "dense" if "dense" in r["params"] else "sparse"
        return f"eroded {style} N={r['n']}"
    return f"{r['family']} N<=60 (proven optima)"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    rows = [r for r in csv.DictReader(open(f"{sys.argv[1]}/results.csv"))
            if r["objective"] in OBJECTIVES and r["valid"] == "true" and not r["error"]
            and r["value"]]
    best = {}
    for r in rows:
        k = (r["instance"], r["objective"])
        best[k] = min(best.get(k, 10**18), int(r["value"]))
    ratios = defaultdict(list)
    secs = defaultdict(list)
    for r in rows:
        if r["algorithm"] == "exact":
            continue
        k = (r["instance"], r["objective"])
        g = (r["objective"], group(r), r["algorithm"])
        ratios[g].append(int(r["value"]) / best[k] if best[k] else 1.0)
        secs[g].append(float(r["seconds"]))
    print("| objective | instances | algorithm | rows | median ratio | worst | within 1.03 | within 1.05 | median s per run |")
    print("|---|---|---|---|---|---|---|---|---|")
    for g in sorted(ratios, key=lambda g: (OBJECTIVES.index(g[0]), g[1], g[2])):
        v = ratios[g]
        print(f"| {g[0]} | {g[1]} | {g[2]} | {len(v)} | {statistics.median(v):.3f} | {max(v):.3f} "
              f"| {sum(x <= 1.03 + 1e-9 for x in v)} | {sum(x <= 1.05 + 1e-9 for x in v)} "
              f"| {statistics.median(secs[g]):.1f} |")


if __name__ == "__main__":
    main()
