#!/usr/bin/env bash
# The soak (docs/soak.md): every reader and every command fed mutated inputs under a
# memory cap (2 GiB of address space) and a timeout (20 s a call); fails on a panic, an abort or
# signal, a hang, or an exit 0 with a result the independent scripts/tour_check.py disagrees with.
#
#   scripts/soak.sh [--short] [--seed S] [--out DIR] [--timeout SECONDS]
#
# --short (the CI form, .ci/run): the reader property tests with 256 cases each and 200
# command-line probes; without it 5000 cases and 2000 probes. Results and the inputs of every
# failing probe go to DIR (default /tmp/mowmill-soak-<stamp>); exit 1 if anything failed.
set -euo pipefail
cd "$(dirname "$0")/.."
short=0
seed=1
out=""
timeout=20
while [ $# -gt 0 ]; do
    case "$1" in
        --short) short=1 ;;
        --seed) seed="$2"; shift ;;
        --out) out="$2"; shift ;;
        --timeout) timeout="$2"; shift ;;
        *) echo "usage: scripts/soak.sh [--short] [--seed S] [--out DIR] [--timeout S]" >&2; exit 2 ;;
    esac
    shift
done
[ -n "$out" ] || out=/tmp/mowmill-soak-$(date -u +%Y%m%dT%H%M%SZ)
if [ -e "$out" ] && [ -n "$(ls -A "$out")" ]; then
    echo "soak: $out exists and is not empty" >&2
    exit 2
fi
mkdir -p "$out/tmp"
if [ "$short" = 1 ]; then cases=256; probes=200; else cases=5000; probes=2000; fi

# The library half: proptest over every parser; its temporary files go under $out.
status=0
echo "soak: reader property tests, $cases cases each (seed $seed)" >&2
if ! TMPDIR="$out/tmp" PROPTEST_CASES=$cases PROPTEST_RNG_SEED=$seed \
    cargo test --release --test soak >"$out/proptest.log" 2>&1; then
    echo "soak: reader property tests FAILED (see $out/proptest.log):" >&2
    grep -E "panicked|minimal failing input|^test .* FAILED" "$out/proptest.log" >&2 || true
    status=1
fi
readers=$(grep -Eo "test result: .* [0-9]+ passed; [0-9]+ failed" "$out/proptest.log" || echo "no result")
echo "soak: reader property tests: $readers" >&2
rm -rf "$out/tmp"
mkdir -p "$out/tmp"

# The command-line half (cargo test built target/release/mowmill). Four probes at a time on 2
# cores: a hung probe (a FIFO read) sleeps, so it should not hold a core.
echo "soak: $probes command-line probes (timeout ${timeout}s, 2 GiB) into $out" >&2
python3 scripts/soak.py --bin target/release/mowmill --out "$out" --seed "$seed" \
    --probes "$probes" --timeout "$timeout" --jobs 4 || status=1
echo "soak: readers: $readers; report: $out/report.txt" >&2
exit $status
