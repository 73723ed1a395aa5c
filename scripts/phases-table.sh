#!/usr/bin/env bash
# docs/measured.md's phases table: where `mowmill solve` spends its time at 10^7 pixels (the
# JSON's `phases`: parse, precondition, run, check) for the linear algorithms, on the speed
# table's instances (seed 1; scripts/speed-table.sh says which), one run each, plus the wall
# time (which also counts freeing the memory at exit). Prints a markdown table.
#
#   scripts/phases-table.sh [--n 10000000]
set -euo pipefail
cd "$(dirname "$0")/.."
n=10000000
while [ $# -gt 0 ]; do
    case "$1" in
        --n) n="$2"; shift 2 ;;
        *) echo "usage: $0 [--n PIXELS]" >&2; exit 2 ;;
    esac
done
cargo build --release --quiet
bin=target/release/mowmill
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$bin" gen random-simple --n "$n" --seed 1 --out "$dir/rs.grid" >/dev/null 2>&1
"$bin" gen random-holed --n "$n" --holes 100 --seed 1 --out "$dir/rh.grid" >/dev/null 2>&1
"$bin" gen random-holed --n "$n" --holes 100 --no-cut --seed 1 --out "$dir/rh-nocut.grid" >/dev/null 2>&1
"$bin" gen band --k $((n / 5)) --out "$dir/band.gg" >/dev/null 2>&1
"$bin" gen thin-eulerian --n "$n" --seed 1 --out "$dir/te.grid" >/dev/null 2>&1
echo "| algorithm | instance | parse | precondition | run | check | wall |"
echo "|---|---|---|---|---|---|---|"
while read -r algo kind file; do
    /usr/bin/time -f "%e" -o "$dir/time" "$bin" solve --algo "$algo" "$dir/$file" --json >"$dir/out.json"
    python3 - "$algo" "$kind" "$dir/out.json" "$dir/time" <<'PY'
import json, sys
algo, kind, out, time = sys.argv[1:]
p = json.load(open(out))["phases"]
wall = open(time).read().split()[-1]
print(f"| `{algo}` | {kind} | {p['parse']:.2f} s | {p['precondition']:.2f} s | "
      f"{p['run']:.2f} s | {p['check']:.2f} s | {wall} s |")
PY
done <<'ROWS'
milling25 rs rs.grid
milling25 rh rh.grid
milling25 band band.gg
tsp65 rs rs.grid
tsp65 band band.gg
holes1325 rh-nocut rh-nocut.grid
star-cover rs rs.grid
star-cover rh rh.grid
star-cover band band.gg
strips-double rs rs.grid
strips-double rh rh.grid
strips-double band band.gg
thin-euler te te.grid
ROWS
