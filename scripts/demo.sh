#!/usr/bin/env bash
# The main job until the benchmark runner lands: generate instances of several families,
# analyse them and draw them under results/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/mowmill
out=results/demo
mkdir -p "$out"
$bin gen random-simple --n 400 --seed 1 --out "$out/simple.grid"
$bin gen random-holed --n 600 --holes 4 --no-cut --seed 2 --out "$out/holed.grid"
$bin gen thin --n 300 --holes 3 --seed 3 --out "$out/thin.grid"
$bin gen donut --k 2 --side 8 --seed 0 --out "$out/donut.grid"
for f in "$out"/*.grid; do
  echo "== $f"
  $bin info "$f"
  $bin draw "$f" --out "${f%.grid}.svg"
  $bin draw "$f" --out "${f%.grid}.png"
done
$bin validate instances/fixtures/square-3x3.grid --tour instances/fixtures/square-3x3.tour.json
$bin draw instances/fixtures/square-3x3.grid --tour instances/fixtures/square-3x3.tour.json --out "$out/square-3x3-tour.svg"
echo "pictures and instances in $out/"
