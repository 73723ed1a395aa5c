#!/usr/bin/env bash
# The validate suite: every registered algorithm against exact optima, best
# checked walks and proven bounds, on every model, and ONE claims table over all of it.
#   scripts/validate.sh [OUT]      (default OUT: results/validate; about an hour on 2 cores)
#
# Parts (each a bench run; a killed run continues where it stopped when started again):
#   OUT                       experiments/validate.toml: grid regions of every family and style
#   OUT-discrete              experiments/validate-discrete.toml: Table 1's rows Discrete and
#                             Restricted-direction
#   OUT-ortho                 experiments/validate-ortho.toml: non-integral orthogonal polygons
#   OUT-structured            experiments/validate-structured.toml: the structured families
#                             (hole lattices, combs, spirals, windows, crossing outlines, rings,
#                             corridor stars) from tens to thousands of pixels
#   OUT-structured-discrete   experiments/validate-structured-discrete.toml: the structured
#                             discrete families (hubs on a path, bridges between straight paths)
#                             from tens to tens of thousands of vertices
#   OUT-coverage4             experiments/validate-coverage4.toml: Theorem 5.6 and Table 1's
#                             length-4 / coverage-4 cell (--coverage4 with and without)
# Then the one claims table over all parts, OUT/claims.{csv,md} and OUT/findings.md (README's
# findings section is spliced from it by scripts/update-readme-tables.sh), the violating
# instances in OUT/findings/, and OUT/sample/: a fixed random sample of the rows that the slow
# test tier re-runs (tests/validate_sample.rs), so a change that moves a number must regenerate
# this. Committed: OUT/claims.{csv,md}, OUT/findings.md, OUT/findings/, OUT/sample/ and each
# part's stats.csv and manifest.json; results.csv, instances/, walks/ and plots/ are regenerated
# (deterministic) and git-ignored.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/validate}
cargo build --release --quiet
# The slow test tier first: the complete-graph references the large-instance matchings rest on.
cargo test --release --test tight --test matching --test boundary -- --ignored
bin=target/release/mowmill

# run DIR CONFIG: one part, resumed when DIR already holds rows.
run() {
  if [ -f "$1/results.csv" ]; then
    "$bin" bench --resume "$1" --config "$2" --jobs "${JOBS:-2}"
  else
    "$bin" bench --config "$2" --out "$1" --jobs "${JOBS:-2}"
  fi
}

parts=(
  "$out:experiments/validate.toml"
  "$out-discrete:experiments/validate-discrete.toml"
  "$out-ortho:experiments/validate-ortho.toml"
  "$out-structured:experiments/validate-structured.toml"
  "$out-structured-discrete:experiments/validate-structured-discrete.toml"
  "$out-coverage4:experiments/validate-coverage4.toml"
)
from=()
for p in "${parts[@]}"; do
  dir=${p%%:*}
  config=${p#*:}
  # bench exits 1 when a registered guarantee is violated: a finding the table reports.
  run "$dir" "$config" || [ $? -eq 1 ]
  # A part holds no claims table of its own: the one table is OUT's.
  rm -f "$dir/claims.csv" "$dir/claims.md"
  from+=(--from "$dir")
done

rm -rf "$out/findings"
# claims exits 1 when a claim is violated: that is a finding to read, not a failed script.
"$bin" claims "${from[@]}" --out "$out" --findings "$out/findings" || [ $? -eq 1 ]

# The fixed random sample of the rows just computed, then the slow test that re-runs it (here,
# after the sample is drawn: a change that moves the numbers must be able to regenerate them).
rm -rf "$out/sample"
"$bin" sample "${from[@]}" --out "$out/sample"
if [ "$out" = results/validate ]; then
  cargo test --release --test validate_sample -- --ignored
else
  "$bin" sample --check "$out/sample" --jobs "${JOBS:-2}"
fi

# The run's page (docs/report.md): the committed results/validate/report.html.
if [ "$out" = results/validate ]; then
  "$bin" report "$out" --tight results/tight --hunt results/hunt
fi
