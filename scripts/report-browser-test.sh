#!/usr/bin/env bash
# Renders a run's report in headless Chromium and checks it from the DOM (docs/report.md):
# one claims row per claim of claims.csv with the same verdicts, every figure rendered (no broken
# image, no empty chart), the table sort works, and no request left the page (Chromium's net
# log holds only the file itself and data: URLs). Installs Debian's chromium when missing.
#
#   scripts/report-browser-test.sh RUN [SCREENSHOT.png [REPORT OPTIONS...]]
#
# RUN is a bench folder; its report is written again to a temporary file. With SCREENSHOT, the
# first screen (1280 x 900) is saved there (README's docs/report.png comes from this).
set -euo pipefail
cd "$(dirname "$0")/.."
run=${1:?usage: scripts/report-browser-test.sh RUN [SCREENSHOT.png]}
shot=${2:-}
shift $(( $# < 2 ? $# : 2 ))  # What is left goes to `mowmill report` (e.g. --tight DIR --hunt DIR).
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "report-browser-test: installing chromium (headless)" >&2
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -q >/dev/null
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q chromium >/dev/null
  browser=$(command -v chromium)
fi
command -v python3 >/dev/null || { echo "report-browser-test: python3 is needed" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
target/release/mowmill report "$run" --out "$tmp/report.html" "$@"
# The claims table the report must show, computed by the claims command itself when the run has
# no claims.csv (a bench folder), else the run's own.
if [ -f "$run/claims.csv" ]; then
  cp "$run/claims.csv" "$tmp/claims.csv"
else
  mkdir -p "$tmp/claims"
  target/release/mowmill claims --from "$run" --tight /nonexistent --hunt /nonexistent --out "$tmp/claims" >/dev/null 2>&1 || true
  cp "$tmp/claims/claims.csv" "$tmp/claims.csv"
fi
flags=(--headless --no-sandbox --disable-gpu --no-first-run --disable-extensions
  --disable-background-networking --disable-component-update --disable-sync
  --user-data-dir="$tmp/profile" --virtual-time-budget=20000)
start=$(date +%s.%N)
"$browser" "${flags[@]}" --log-net-log="$tmp/net.json" --dump-dom "file://$tmp/report.html#selftest" \
  > "$tmp/dom.html" 2> "$tmp/chromium.log" || { cat "$tmp/chromium.log" >&2; exit 1; }
end=$(date +%s.%N)
# The net-log check must be able to fail: a page with one outside image must be caught.
echo '<html><body><img src="http://example.invalid/planted.png"></body></html>' > "$tmp/planted.html"
"$browser" "${flags[@]}" --log-net-log="$tmp/planted-net.json" --dump-dom "file://$tmp/planted.html" \
  > /dev/null 2>> "$tmp/chromium.log" || true
if [ -n "$shot" ]; then
  "$browser" "${flags[@]}" --hide-scrollbars --window-size=1280,900 --screenshot="$tmp/shot.png" \
    "file://$tmp/report.html" 2>> "$tmp/chromium.log" >/dev/null
  cp "$tmp/shot.png" "$shot"
fi
python3 - "$tmp" "$start" "$end" <<'PY'
import csv, html, json, os, re, sys
tmp, start, end = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
dom = open(os.path.join(tmp, "dom.html"), encoding="utf-8").read()
m = re.search(r'<pre id="selftest-result"[^>]*>(.*?)</pre>', dom, re.S)
if not m or not m.group(1).strip():
    sys.exit("report-browser-test: the page's self-test did not run (no #selftest-result)")
st = json.loads(html.unescape(m.group(1)))
with open(os.path.join(tmp, "claims.csv"), newline="", encoding="utf-8") as f:
    want = [r["verdict"] for r in csv.DictReader(f)]
errors = []
if st["claim_rows"] != len(want):
    errors.append(f"claims table: {st['claim_rows']} rows, claims.csv has {len(want)}")
if st["verdicts"] != want:
    errors.append(f"claims table verdicts differ from claims.csv: {st['verdicts'][:5]}... vs {want[:5]}...")
if st["broken"]:
    errors.append(f"{len(st['broken'])} figure(s) not rendered: {st['broken'][:5]}")
if st["images"] + st["charts"] == 0:
    errors.append("no figure at all")
if st["sort_ok"] is not True:
    errors.append(f"sorting the claims table by 'decided' failed ({st['sort_ok']})")
def page_requests(name):
    """The URLs of the net log's requests that the page made: the browser's own background
    requests (update checks, time sync) are logged at IDLE priority; the page's loads at
    LOWEST and above."""
    net = open(os.path.join(tmp, name), encoding="utf-8", errors="replace").read()
    found = set()
    for m in re.finditer(r'\{[^{}]*"priority":"([A-Z]+)"[^{}]*"url":"([^"]+)"[^{}]*\}', net):
        prio, url = m.groups()
        if prio != "IDLE" and not url.startswith("data:") and not url.startswith("file://"):
            found.add(url)
    return sorted(found)
if "http://example.invalid/planted.png" not in page_requests("planted-net.json"):
    errors.append("the request check missed the planted page's outside image: it cannot be trusted")
outside = page_requests("net.json") + [u for u in st.get("resources", []) if not u.startswith(("data:", "file:"))]
if outside:
    errors.append(f"{len(outside)} request(s) left the page: {outside[:5]}")
size = os.path.getsize(os.path.join(tmp, "report.html"))
print(f"report-browser-test: {st['claim_rows']} claim rows, {st['charts']} charts and {st['images']} images rendered, "
      f"sort ok, {len(outside)} outside requests, {size/1e6:.2f} MB, rendered in {st['render_ms']} ms "
      f"(browser run {end-start:.1f} s)")
if errors:
    for e in errors:
        print("report-browser-test: FAIL: " + e, file=sys.stderr)
    sys.exit(1)
PY
