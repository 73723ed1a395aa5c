#!/usr/bin/env bash
# Rewrites docs/algorithms.md's algorithm tables (between <!-- algos:begin --> and <!-- algos:end -->)
# from the registry: the output of `mowmill algos --markdown`. tests/registry.rs fails while
# they differ.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
tables=$(mktemp)
trap 'rm -f "$tables" docs/algorithms.md.new' EXIT
target/release/mowmill algos --markdown >"$tables"
grep -q '^<!-- algos:begin -->$' docs/algorithms.md && grep -q '^<!-- algos:end -->$' docs/algorithms.md || {
    echo "docs/algorithms.md has no <!-- algos:begin --> / <!-- algos:end --> lines" >&2
    exit 2
}
awk -v tables="$tables" '
    /^<!-- algos:begin -->$/ { print; while ((getline line < tables) > 0) print line; skip = 1; next }
    /^<!-- algos:end -->$/ { skip = 0 }
    !skip { print }
' docs/algorithms.md >docs/algorithms.md.new
mv docs/algorithms.md.new docs/algorithms.md
echo "docs/algorithms.md: algorithm tables updated from mowmill algos --markdown"

# README's findings section (between <!-- findings:begin --> and <!-- findings:end -->) from the
# committed claims table's findings (results/validate/findings.md, written by `mowmill claims
# --out results/validate`). tests/readme.rs fails while they differ.
findings=results/validate/findings.md
[ -f "$findings" ] || { echo "no $findings: run scripts/validate.sh first" >&2; exit 2; }
grep -q '^<!-- findings:begin -->$' README.md && grep -q '^<!-- findings:end -->$' README.md || {
    echo "README.md has no <!-- findings:begin --> / <!-- findings:end --> lines" >&2
    exit 2
}
awk -v f="$findings" '
    /^<!-- findings:begin -->$/ { print; while ((getline line < f) > 0) print line; skip = 1; next }
    /^<!-- findings:end -->$/ { skip = 0 }
    !skip { print }
' README.md >README.md.new
mv README.md.new README.md
echo "README.md: findings updated from $findings"
