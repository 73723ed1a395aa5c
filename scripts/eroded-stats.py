#!/usr/bin/env python3
"""Mean statistics of eroded instances per size and variant, from `mowmill info --json`:
holes, boundary pixels, degree-2 pixels, cut vertices and the minimum strip cover, each per
pixel. Files are grouped by the `_<N>_<dense|sparse>_` in their names, which both the 2016
thesis's files (fc_1000_sparse_0.gg) and `gen` names of this form (eroded_1000_sparse_0.grid)
carry.

    scripts/eroded-stats.py [--mowmill target/release/mowmill] FILE...
"""
import argparse
import json
import re
import subprocess
import sys
from collections import defaultdict

KEYS = ["holes", "boundary", "degree2", "cut_vertices", "strip_cover"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mowmill", default="target/release/mowmill")
    ap.add_argument("files", nargs="+")
    args = ap.parse_args()
    groups = defaultdict(list)
    for f in args.files:
        m = re.search(r"_(\d+)_(dense|sparse)_", f)
        if not m:
            sys.exit(f"{f}: no _<N>_<dense|sparse>_ in the name")
        out = subprocess.run([args.mowmill, "info", f, "--json"], capture_output=True, text=True)
        if out.returncode != 0:
            sys.exit(f"{f}: mowmill info failed: {out.stderr.strip()}")
        groups[(int(m.group(1)), m.group(2))].append(json.loads(out.stdout))
    print("| N | variant | files | holes | boundary / N | degree-2 / N | cut vertices / N | strip cover / N |")
    print("|---|---|---|---|---|---|---|---|")
    for (n, variant), infos in sorted(groups.items()):
        mean = {k: sum(i[k] for i in infos) / len(infos) for k in KEYS}
        per = lambda k: f"{mean[k] / n:.3f}"
        print(f"| {n} | {variant} | {len(infos)} | {mean['holes']:.1f} | {per('boundary')} | "
              f"{per('degree2')} | {per('cut_vertices')} | {per('strip_cover')} |")


if __name__ == "__main__":
    main()
