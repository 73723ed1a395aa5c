#!/usr/bin/env bash
# docs/measured.md's speed table: every registered algorithm, end to end (`mowmill solve`: parse, run,
# merge, the checker's recount), on generated regions of 10^5, 10^6 and 10^7 pixels (by default), one run
# each, one thread. Prints a markdown table: wall seconds and peak memory per size, or what
# stopped the run ("> T s" past the timeout, "exit K" for a failure).
#
#   scripts/speed-table.sh [--sizes "10000 100000 1000000"] [--timeout 300] [--rows "ALGO KIND..."]
#                          [--csv FILE]
#
# --csv also writes every cell as a row of FILE (algorithm,instance,n,seconds,peak_mb,status;
# status ok, finding for exit 1, timeout, exit K), the input of
# `scripts/speed-plot.py FILE OUT.svg` (the log-log plot and the fitted exponents).
#
# --rows measures only the given rows (lines of an algorithm and its instance kinds, as in the
# list at the end).
#
# Instances (seed 1): rs = random-simple, rh = random-holed --holes 100 (--no-cut for
# holes1325, which needs no local cut vertices), band = the diagonal band B_k with k = N/5,
# thin = thin pockets, bd = boundary-rooms (every pixel a boundary pixel, exactly N, at every
# size: the `boundary` family gives up on its shape above about 10^5 pixels), te =
# thin-eulerian (thin, every pixel of even degree, N within N/50 + 32), lawn = lawn-scattered.
# tsp65 needs a region without holes.
set -euo pipefail
cd "$(dirname "$0")/.."
sizes="100000 1000000 10000000"
timeout=300
rows=""
csv=""
while [ $# -gt 0 ]; do
    case "$1" in
        --sizes) sizes="$2"; shift 2 ;;
        --timeout) timeout="$2"; shift 2 ;;
        --rows) rows="$2"; shift 2 ;;
        --csv) csv="$2"; shift 2 ;;
        *) echo "usage: $0 [--sizes \"N1 N2 ...\"] [--timeout SECONDS]" >&2; exit 2 ;;
    esac
done
cargo build --release --quiet
bin=target/release/mowmill
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
if [ -n "$csv" ]; then echo "algorithm,instance,n,seconds,peak_mb,status" >"$csv"; fi

record() { # algo kind n seconds peak_mb status -> one CSV row, when asked for
    if [ -n "$csv" ]; then echo "$1,$2,$3,$4,$5,$6" >>"$csv"; fi
}

instance() { # kind n -> path (generated once)
    local kind=$1 n=$2 f="$dir/$1-$2.grid"
    # The band's .grid picture would be mostly empty (its bounding box is (N/5)^2): a pixel list.
    if [ "$kind" = band ]; then f="$dir/$1-$2.gg"; fi
    if [ ! -f "$f" ]; then
        case "$kind" in
            rs) "$bin" gen random-simple --n "$n" --seed 1 --out "$f" ;;
            rh) "$bin" gen random-holed --n "$n" --holes 100 --seed 1 --out "$f" ;;
            rh-nocut) "$bin" gen random-holed --n "$n" --holes 100 --no-cut --seed 1 --out "$f" ;;
            band) "$bin" gen band --k $((n / 5)) --out "$f" ;;
            thin) "$bin" gen thin --n "$n" --seed 1 --out "$f" ;;
            bd) "$bin" gen boundary-rooms --n "$n" --seed 1 --out "$f" ;;
            te) "$bin" gen thin-eulerian --n "$n" --seed 1 --out "$f" ;;
            lawn) "$bin" gen lawn-scattered --n "$n" --seed 1 --out "$f" ;;
        esac >/dev/null 2>&1
    fi
    echo "$f"
}

measure() { # algo kind n -> one cell
    local f rc
    f=$(instance "$2" "$3")
    rc=0
    timeout "$timeout" /usr/bin/time -f "%e %M" -o "$dir/time" "$bin" solve --algo "$1" "$f" \
        >/dev/null 2>"$dir/err" || rc=$?
    if [ "$rc" = 124 ]; then
        record "$1" "$2" "$3" "$timeout" "" timeout
        echo "> $timeout s"
    elif [ "$rc" != 0 ] && [ "$rc" != 1 ]; then
        record "$1" "$2" "$3" "" "" "exit $rc"
        echo "exit $rc"
    else
        # shellcheck disable=SC2046 # two numbers: seconds and peak memory in MB
        record "$1" "$2" "$3" $(awk '{ printf "%s %d", $1, $2 / 1024 }' "$dir/time") \
            "$([ "$rc" = 1 ] && echo finding || echo ok)"
        awk '{ printf "%.2f s, %d MB", $1, $2 / 1024 }' "$dir/time"
        # Exit 1: the run finished but the checker or a guarantee failed (a finding).
        if [ "$rc" = 1 ]; then echo -n " (exit 1)"; fi
    fi
}

header="| algorithm | instance |"
rule="|---|---|"
for n in $sizes; do header="$header N = $n |"; rule="$rule---|"; done
echo "$header"
echo "$rule"
all_rows="\
milling25 rs rh band
tsp65 rs band
holes1325 rh-nocut
star-cover rs rh band
strips-double rs rh band
strips-matching rs rh band
thin-cc thin
thin-merge thin
boundary-cc bd
thin-euler te
lawn-mst lawn rs
lawn-christofides lawn rs
lawn-2opt lawn rs
lawn-box lawn rs
"
while read -r algo kinds; do
    [ -n "$algo" ] || continue
    for kind in $kinds; do
        row="| \`$algo\` | $kind |"
        for n in $sizes; do row="$row $(measure "$algo" "$kind" "$n") |"; done
        echo "$row"
    done
done <<<"${rows:-$all_rows}"
