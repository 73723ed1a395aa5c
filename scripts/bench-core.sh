#!/usr/bin/env bash
# Times the core at scale: generating and analysing 10^6-pixel regions (docs/measured.md, "Core").
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/mowmill
dir=$(mktemp -d)
run() { /usr/bin/time -f "%e s  %M KB  mowmill $*" "$bin" "$@" >/dev/null 2>"$dir/err" || { cat "$dir/err"; exit 1; }; tail -1 "$dir/err"; }
run gen rect --width 1000 --height 1000 --seed 1 --out "$dir/rect.grid"
run gen random-simple --n 1000000 --seed 1 --out "$dir/simple.grid"
run gen random-simple --n 1000000 --no-cut --seed 1 --out "$dir/simple-nocut.grid"
run gen random-holed --n 1000000 --holes 100 --no-cut --seed 1 --out "$dir/holed.grid"
for f in rect simple simple-nocut holed; do run info "$dir/$f.grid" --json; done
run draw "$dir/holed.grid" --out "$dir/holed.png"
rm -rf "$dir"
