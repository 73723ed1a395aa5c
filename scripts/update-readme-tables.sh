#!/usr/bin/env bash
# Rewrites README.md's algorithm tables (between <!-- algos:begin --> and <!-- algos:end -->)
# from the registry: the output of `mowmill algos --markdown`. tests/registry.rs fails while
# they differ.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
tables=$(mktemp)
trap 'rm -f "$tables" README.md.new' EXIT
target/release/mowmill algos --markdown >"$tables"
grep -q '^<!-- algos:begin -->$' README.md && grep -q '^<!-- algos:end -->$' README.md || {
    echo "README.md has no <!-- algos:begin --> / <!-- algos:end --> lines" >&2
    exit 2
}
awk -v tables="$tables" '
    /^<!-- algos:begin -->$/ { print; while ((getline line < tables) > 0) print line; skip = 1; next }
    /^<!-- algos:end -->$/ { skip = 0 }
    !skip { print }
' README.md >README.md.new
mv README.md.new README.md
echo "README.md: algorithm tables updated from mowmill algos --markdown"
