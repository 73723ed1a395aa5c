#!/usr/bin/env python3
"""Compares two mowmill run directories: their results.csv row by row apart from timings
(the `seconds` and `run_id` columns), and their stats.csv exactly (it has no timing column).
Prints every difference and exits 1 if there is any, 0 if the runs agree.

    scripts/compare-runs.py RUN_A RUN_B
"""
import csv
import sys

# Timings and the run's name differ between two runs of the same suite; nothing else may.
IGNORED = {"seconds", "run_id"}
# A row's identity, as `mowmill merge` keys it.
KEY = ("instance", "algorithm", "objective")


def read_rows(run):
    """The rows of RUN/results.csv keyed by (instance, algorithm, objective), plus the keys
    that occur more than once (a resumed run must never write a row twice)."""
    rows, dups = {}, []
    with open(f"{run}/results.csv", newline="") as f:
        reader = csv.DictReader(f)
        for row in reader:
            key = tuple(row[k] for k in KEY)
            if key in rows:
                dups.append(key)
            rows[key] = {k: v for k, v in row.items() if k not in IGNORED}
    return reader.fieldnames, rows, dups


def main(a, b):
    problems = []
    cols_a, rows_a, dups_a = read_rows(a)
    cols_b, rows_b, dups_b = read_rows(b)
    if cols_a != cols_b:
        problems.append(f"results.csv columns differ:\n  {a}: {cols_a}\n  {b}: {cols_b}")
    for run, dups in ((a, dups_a), (b, dups_b)):
        for key in dups:
            problems.append(f"{run}: row {key} occurs more than once")
    for key in sorted(rows_a.keys() - rows_b.keys()):
        problems.append(f"row {key} only in {a}")
    for key in sorted(rows_b.keys() - rows_a.keys()):
        problems.append(f"row {key} only in {b}")
    for key in sorted(rows_a.keys() & rows_b.keys()):
        ra, rb = rows_a[key], rows_b[key]
        for col in sorted(set(ra) | set(rb)):
            if ra.get(col) != rb.get(col):
                problems.append(f"row {key} column {col}: {ra.get(col)!r} != {rb.get(col)!r}")
    # stats.csv is derived from the rows without timings, so it must agree byte for byte.
    with open(f"{a}/stats.csv") as fa, open(f"{b}/stats.csv") as fb:
        sa, sb = fa.read().splitlines(), fb.read().splitlines()
    if sa != sb:
        only_a = [l for l in sa if l not in sb]
        only_b = [l for l in sb if l not in sa]
        problems.append(
            "stats.csv differs:\n"
            + "".join(f"  only in {a}: {l}\n" for l in only_a[:20])
            + "".join(f"  only in {b}: {l}\n" for l in only_b[:20])
            + ("  (same lines, different order)\n" if not only_a and not only_b else "")
        )
    for p in problems[:200]:
        print(p)
    if len(problems) > 200:
        print(f"... and {len(problems) - 200} more differences")
    if problems:
        print(f"compare-runs: {len(problems)} difference(s) between {a} and {b}")
        return 1
    print(f"compare-runs: {len(rows_a)} rows and stats.csv agree apart from timings: {a} = {b}")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
