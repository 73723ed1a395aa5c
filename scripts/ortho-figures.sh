#!/usr/bin/env bash
# Draws the figures of orthogonal polygons with arbitrary coordinates into
# results/figures/: a generated non-integral polygon, and for each algorithm its tour, the area
# the cutter sweeps along it and δB (the contour of the centre positions), checked exactly
# (the caption is the checker's verdict). One figure per algorithm: ortho-ALGO.svg.
#
# Environment (defaults in brackets): FAMILY [ortho-holed], N [16], SEED [6],
# ALGOS ["corollary4 strips-contour star-contour"]. An algorithm this build does not know is skipped with
# a note; any other failure stops the script.
set -euo pipefail
cd "$(dirname "$0")/.."
FAMILY=${FAMILY:-ortho-holed}
N=${N:-16}
SEED=${SEED:-6}
ALGOS=${ALGOS:-corollary4 strips-contour star-contour}
cargo build --release --quiet
bin=target/release/mowmill
out=results/figures
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir -p "$out"

poly="$dir/$FAMILY-$N-$SEED.wkt"
"$bin" gen "$FAMILY" --n "$N" --seed "$SEED" --out "$poly"
for algo in $ALGOS; do
  tour="$dir/$algo.json"
  # `solve` exits 1 for an invalid tour: still drawn (the figure shows why), not fatal here.
  status=0
  "$bin" solve "$poly" --algo "$algo" --tour-out "$tour" >"$dir/$algo.out" 2>"$dir/$algo.err" ||
    status=$?
  if [ ! -s "$tour" ]; then
    # Refused by name: by clap's list of algorithms, or by `solve` on an ortho polygon.
    if grep -qE "invalid value '$algo'|\(not $algo\)" "$dir/$algo.err"; then
      echo "ortho-figures: skipping $algo: this build does not know it ($(head -1 "$dir/$algo.err"))" >&2
      continue
    fi
    cat "$dir/$algo.err" >&2
    echo "ortho-figures: $algo wrote no tour (exit $status)" >&2
    exit 1
  fi
  "$bin" draw "$poly" --tour "$tour" --out "$out/ortho-$algo.svg" \
    --title "$algo on $FAMILY (n = $N, seed $SEED): tour, swept area and δB"
done
