#!/usr/bin/env python3
"""An independent recount of a milling tour, for the soak (docs/soak.md).

    python3 scripts/tour_check.py INSTANCE.grid|.gg|.csv TOUR.json

prints {"valid", "length", "turns", "error"} as JSON. Python integers do not wrap, so a move
from x = 2^31 - 1 to x = -2^31 is not a unit move here. Rules as in crates/core/src/checker.rs (milling):
every step of a closed walk (wrap-around included) moves to a 4-neighbour, every visited pixel
is in the region, every pixel of the region is visited; turns 0 / 1 / 2 per vertex, a
one-pixel walk has length 0 and 4 turns. Only the plain formats are read: `.grid` (`;`
comments, `#` pixel, last row y = 0) and pixel lists (`x y` or `x,y` per line, `#` comments,
an optional header).
"""

import json
import sys


def read_region(path):
    text = open(path, encoding="utf-8").read()
    if path.lower().endswith((".gg", ".csv")):
        pixels = set()
        first = True
        for line in text.splitlines():
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            parts = line.replace(",", " ").split()
            try:
                x, y = (int(p) for p in parts)
            except ValueError:
                if first:
                    first = False
                    continue
                raise
            first = False
            pixels.add((x, y))
        return pixels
    rows = [l for l in text.splitlines() if not l.startswith(";")]
    pixels = set()
    for r, row in enumerate(rows):
        y = len(rows) - 1 - r
        for x, c in enumerate(row):
            if c == "#":
                pixels.add((x, y))
            elif c != ".":
                raise ValueError(f"bad character {c!r}")
    return pixels


def direction(a, b):
    d = (b[0] - a[0], b[1] - a[1])
    return d if abs(d[0]) + abs(d[1]) == 1 else None


def turn(d, e):
    if d == e:
        return 0
    if d == (-e[0], -e[1]):
        return 2
    return 1


def check(region, tour):
    """Returns (valid, length, turns, error); raises ValueError on a malformed tour."""
    cycles = tour["cycles"]
    if not isinstance(cycles, list):
        raise ValueError("cycles is not a list")
    walks = []
    for c in cycles:
        walk = []
        for p in c:
            if not (isinstance(p, list) and len(p) == 2 and all(type(v) is int for v in p)):
                raise ValueError(f"bad pixel {p!r}")
            walk.append((p[0], p[1]))
        walks.append(walk)
    length = turns = 0
    if not walks:
        return False, 0, 0, "no cycles"
    seen = set()
    for i, walk in enumerate(walks):
        m = len(walk)
        if m == 0:
            return False, length, turns, f"cycle {i} is empty"
        if m == 1:
            length, turns = length, turns + 4
        else:
            dirs = []
            for k in range(m):
                d = direction(walk[k], walk[(k + 1) % m])
                if d is None:
                    return False, length, turns, f"cycle {i} step {k} is not a unit move"
                dirs.append(d)
            length += m
            turns += sum(turn(dirs[k - 1], dirs[k]) for k in range(m))
        for p in walk:
            if p not in region:
                return False, length, turns, f"pixel {p} outside the region"
            seen.add(p)
    if len(seen) != len(region):
        return False, length, turns, f"{len(region) - len(seen)} pixels not visited"
    return True, length, turns, None


def main():
    region = read_region(sys.argv[1])
    tour = json.load(open(sys.argv[2], encoding="utf-8"))
    valid, length, turns, error = check(region, tour)
    print(json.dumps({"valid": valid, "length": length, "turns": turns, "error": error}))


if __name__ == "__main__":
    main()
