#!/usr/bin/env bash
# Checks scripts/setup.sh's libclang detection against fake library trees (no install).
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
expect() { # dir-contents expected-output
  rm -rf "$tmp/lib" && mkdir -p "$tmp/lib"
  for f in $1; do touch "$tmp/lib/$f"; done
  got=$(SETUP_LIB_DIRS="$tmp/lib" SETUP_DRY_RUN=1 bash scripts/setup.sh 2>/dev/null)
  if [ "$got" != "$2" ]; then
    echo "test-setup: with {$1}: expected '$2', got '$got'" >&2
    exit 1
  fi
}
expect "libclang-cpp.so.14" "setup: would install libclang"
expect "" "setup: would install libclang"
expect "libclang-cpp.so.14 libclang-14.so.1" "setup: would install nothing"
expect "libclang.so" "setup: would install nothing"
expect "libclang.so.1" "setup: would install nothing"
expect "libclang-14.so" "setup: would install nothing"
echo "test-setup: libclang detection ok" >&2
