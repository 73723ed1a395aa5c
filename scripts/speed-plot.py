#!/usr/bin/env python3
"""Time against N, log-log, from the CSV of `scripts/speed-table.sh --csv FILE`.

    scripts/speed-plot.py SPEED.csv OUT.svg

Writes one self-contained SVG (one line per algorithm and instance kind, finished runs only)
and prints a markdown table of the fitted exponent per row: the least-squares slope of
log(seconds) against log(N). Only runs of at least MIN_SECONDS enter the fit (below that the
process start and the parse of a tiny file dominate, so the slope would say nothing about the
algorithm); a row with fewer than two such runs gets no exponent. Standard library only.
"""
import csv
import math
import sys

MIN_SECONDS = 0.05
PALETTE = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
           "#7f7f7f", "#bcbd22", "#17becf"]
DASHES = ["", "6,3", "2,2", "8,3,2,3"]


def read(path):
    rows = {}
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            key = (r["algorithm"], r["instance"])
            rows.setdefault(key, [])
            if r["status"] in ("ok", "finding"):
                rows[key].append((int(r["n"]), float(r["seconds"]), float(r["peak_mb"])))
    return rows


def slope(points):
    pts = [(math.log10(n), math.log10(s)) for n, s, _ in points if s >= MIN_SECONDS]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx if sxx > 0 else None


def svg(rows, out):
    width, height, left, right, top, bottom = 900, 560, 70, 260, 20, 50
    pts = [p for v in rows.values() for p in v]
    if not pts:
        sys.exit("speed-plot: no finished run in the CSV")
    x0 = math.floor(math.log10(min(n for n, _, _ in pts)))
    x1 = math.ceil(math.log10(max(n for n, _, _ in pts)))
    y0 = math.floor(math.log10(max(min(s for _, s, _ in pts), 1e-3)))
    y1 = math.ceil(math.log10(max(s for _, s, _ in pts)))
    x1, y1 = max(x1, x0 + 1), max(y1, y0 + 1)

    def px(n):
        return left + (math.log10(n) - x0) / (x1 - x0) * (width - left - right)

    def py(s):
        s = max(s, 10 ** y0)
        return height - bottom - (math.log10(s) - y0) / (y1 - y0) * (height - top - bottom)

    o = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
         f'font-family="sans-serif" font-size="12">',
         f'<rect width="{width}" height="{height}" fill="white"/>']
    for e in range(x0, x1 + 1):
        x = px(10 ** e)
        o.append(f'<line x1="{x:.1f}" y1="{top}" x2="{x:.1f}" y2="{height - bottom}" stroke="#ddd"/>')
        o.append(f'<text x="{x:.1f}" y="{height - bottom + 16}" text-anchor="middle">10^{e}</text>')
    for e in range(y0, y1 + 1):
        y = py(10 ** e)
        o.append(f'<line x1="{left}" y1="{y:.1f}" x2="{width - right}" y2="{y:.1f}" stroke="#ddd"/>')
        o.append(f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end">{10.0 ** e:g} s</text>')
    o.append(f'<text x="{(left + width - right) / 2}" y="{height - 12}" text-anchor="middle">'
             'N (pixels)</text>')
    for k, ((algo, kind), points) in enumerate(sorted(rows.items())):
        if not points:
            continue
        colour, dash = PALETTE[k % len(PALETTE)], DASHES[(k // len(PALETTE)) % len(DASHES)]
        line = " ".join(f"{px(n):.1f},{py(s):.1f}" for n, s, _ in sorted(points))
        o.append(f'<polyline points="{line}" fill="none" stroke="{colour}" stroke-width="2" '
                 f'stroke-dasharray="{dash}"><title>{algo} {kind}</title></polyline>')
        for n, s, mb in points:
            o.append(f'<circle cx="{px(n):.1f}" cy="{py(s):.1f}" r="3" fill="{colour}">'
                     f'<title>{algo} {kind} N={n}: {s:.2f} s, {mb:.0f} MB</title></circle>')
        b = slope(points)
        label = f"{algo} {kind}" + (f" (N^{b:.2f})" if b is not None else "")
        ly = top + 10 + 16 * k
        o.append(f'<line x1="{width - right + 10}" y1="{ly - 4}" x2="{width - right + 30}" '
                 f'y2="{ly - 4}" stroke="{colour}" stroke-width="2" stroke-dasharray="{dash}"/>')
        o.append(f'<text x="{width - right + 36}" y="{ly}">{label}</text>')
    o.append("</svg>")
    with open(out, "w") as f:
        f.write("\n".join(o) + "\n")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: speed-plot.py SPEED.csv OUT.svg")
    rows = read(sys.argv[1])
    svg(rows, sys.argv[2])
    print("| algorithm | instance | fitted exponent (seconds ∝ N^b) |")
    print("|---|---|---|")
    for (algo, kind), points in sorted(rows.items()):
        b = slope(points)
        print(f"| `{algo}` | {kind} | {'–' if b is None else f'{b:.2f}'} |")


if __name__ == "__main__":
    main()
