#!/usr/bin/env bash
# Regenerates the committed CI baseline (results/baseline/) from experiments/ci.toml.
# Run it only on purpose, and say in the commit why the ratios changed.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
rm -rf results/baseline
target/release/mowmill bench --config experiments/ci.toml --out results/baseline --jobs 2
# The gate reads all three: results.csv (compared instance by instance), manifest.json (the
# config digest and row count) and stats.csv (checked against results.csv, the group summary).
# Plots and instance files are not needed in git.
rm -rf results/baseline/plots results/baseline/instances
target/release/mowmill gate --baseline results/baseline/stats.csv --current results/baseline
