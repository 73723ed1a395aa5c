#!/usr/bin/env bash
# Draws the discrete-milling figures into results/figures/: a tour on 50
# hexagonal cells (the star cover's, and a minimum-turn one) and on 35 voxels with a cavity,
# drawn one panel per z-layer (the minimum-turn tour, and the star cover's).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/mowmill
out=results/figures
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

"$bin" gen hex --n 50 --seed 1 --out "$dir/hex.hex"
"$bin" solve --algo star-cover "$dir/hex.hex" --tour-out "$dir/hex-star.json" >/dev/null
"$bin" exact "$dir/hex.hex" --objective turns --tour-out "$dir/hex-opt.json" >/dev/null
"$bin" draw "$dir/hex.hex" --tour "$dir/hex-star.json" --out "$out/discrete-hex-star-cover.svg" \
  --title "50 hexagonal cells: the star cover's tour (Theorem 5.1, Corollary 5.1)"
"$bin" draw "$dir/hex.hex" --tour "$dir/hex-opt.json" --out "$out/discrete-hex-optimal.svg" \
  --title "50 hexagonal cells: a minimum-turn tour (exact)"

"$bin" gen voxel --n 35 --holes 1 --seed 2 --out "$dir/vox.vox"
"$bin" solve --algo star-cover "$dir/vox.vox" --tour-out "$dir/vox-star.json" >/dev/null
"$bin" exact "$dir/vox.vox" --objective turns --tour-out "$dir/vox-opt.json" >/dev/null
"$bin" draw "$dir/vox.vox" --tour "$dir/vox-opt.json" --out "$out/discrete-voxel-tour.svg" \
  --title "35 voxels with a cavity: a minimum-turn tour (exact), layer by layer"
"$bin" draw "$dir/vox.vox" --tour "$dir/vox-star.json" --out "$out/discrete-voxel-star-cover.svg" \
  --title "35 voxels with a cavity: the star cover's tour, layer by layer"
