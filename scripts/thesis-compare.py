#!/usr/bin/env python3
"""Set a bench run on the 2016 thesis's instances beside the thesis's own results.

For every instance (fc_<N>_<dense|sparse>_<seed>) and objective (cc-turns: the thesis's F*-CC
solvers; turns: F*-T*), the thesis's value is the one any of its formulations proved within its
900 s (a row with a value; `OutOfTime` rows have none). mowmill's exact row gives value, bound and
status. The script fails (exit 1) on a contradiction between the two independent solvers:
  * mowmill proved an optimum that differs from a value the thesis proved;
  * a value the thesis proved lies below mowmill's lower bound or above mowmill's walk's value;
  * the thesis's formulations disagree with each other.
It prints one table per instance and one per size band (solved fractions of both).

    scripts/thesis-compare.py RUN_DIR instances/thesis/results/fc.csv
"""
import csv
import re
import sys
from collections import defaultdict

OBJ = {"cc-turns": "CC", "turns": "T"}


def thesis_values(path):
    vals = defaultdict(set)  # (instance, "CC"|"T") -> proved values
    tried = set()
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            cols = line.rstrip("\n").split("\t")
            inst, solver = cols[0].removesuffix(".gg"), cols[1]
            kind = "CC" if solver.endswith("-CC") else "T"
            tried.add((inst, kind))
            if cols[2] != "OutOfTime":
                vals[(inst, kind)].add(round(float(cols[2])))
    return vals, tried


def band(n):
    return "100-999" if n < 1000 else f"{n // 500 * 500}-{n // 500 * 500 + 499}"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    run, fc = sys.argv[1], sys.argv[2]
    vals, tried = thesis_values(fc)
    bad = []
    rows = []
    bands = defaultdict(lambda: [0, 0, 0, 0])  # ours proven, thesis proven, count, -
    with open(f"{run}/results.csv") as f:
        for r in csv.DictReader(f):
            if r["algorithm"] != "exact" or r["objective"] not in OBJ:
                continue
            m = re.search(r"fc_(\d+)_(dense|sparse)_(\d+)", r["instance"])
            if not m:
                continue
            inst, kind = m.group(0), OBJ[r["objective"]]
            if (inst, kind) not in tried:
                continue
            tv = vals.get((inst, kind), set())
            if len(tv) > 1:
                bad.append(f"{inst} {kind}: the thesis's formulations disagree: {sorted(tv)}")
            t = min(tv) if tv else None
            if r["error"] or r["valid"] != "true":
                bad.append(f"{inst} {r['objective']}: mowmill row has error {r['error']!r}")
                continue
            value, lb, status = int(r["value"]), int(float(r["lower_bound"])), r["opt_status"]
            if t is not None:
                if status == "optimal" and value != t:
                    bad.append(f"{inst} {kind}: mowmill optimum {value} != thesis {t}")
                if not lb <= t <= value:
                    bad.append(f"{inst} {kind}: thesis {t} outside mowmill's [{lb}, {value}]")
            gap = 0.0 if value == 0 else (value - lb) / value
            rows.append((int(m.group(1)), m.group(2), inst, r["objective"], value, lb, status,
                         float(r["seconds"]), t, gap))
            b = bands[(band(int(m.group(1))), m.group(2), r["objective"])]
            b[0] += status == "optimal"
            b[1] += t is not None
            b[2] += 1
    rows.sort()
    print("| instance | objective | mowmill (120 s) | status | s | thesis (900 s) |")
    print("|---|---|---|---|---|---|")
    for n, _, inst, obj, value, lb, status, s, t, gap in rows:
        ours = f"{value}" if status == "optimal" else f"{value} ≥ {lb} (gap {100 * gap:.1f}%)"
        print(f"| {inst} | {obj} | {ours} | {status} | {s:.0f} | {t if t is not None else 'out of time'} |")
    print()
    print("| pixels | variant | objective | mowmill proven | thesis proven |")
    print("|---|---|---|---|---|")
    for (b, var, obj), (ours, theirs, count, _) in sorted(bands.items(), key=lambda kv: (int(kv[0][0].split("-")[0]), kv[0][1:])):
        print(f"| {b} | {var} | {obj} | {ours}/{count} | {theirs}/{count} |")
    print()
    if bad:
        print("CONTRADICTIONS:")
        for b in bad:
            print("  " + b)
        sys.exit(1)
    print(f"{len(rows)} rows, no contradiction with the thesis's proved values")


if __name__ == "__main__":
    main()
