#!/usr/bin/env python3
"""A minimal outside algorithm for mowmill: walk the depth-first-search tree of the pixels
there and back (a milling tour of length 2(N - 1) of a connected region).

Usage: dfs_tour.py INSTANCE.grid TOUR_OUT.json  (mowmill fills in {instance} and {tour_out}).
"""
import json
import sys

grid, tour_out = sys.argv[1], sys.argv[2]
rows = [line.rstrip("\r\n") for line in open(grid) if not line.startswith(";")]
# The first row is the highest y, the last row is y = 0; '#' is a pixel.
pixels = {(x, len(rows) - 1 - i) for i, row in enumerate(rows) for x, c in enumerate(row) if c == "#"}

start = min(pixels)
walk, seen = [start], {start}
stack = [(start, iter([(1, 0), (0, 1), (-1, 0), (0, -1)]))]
while stack:
    (x, y), steps = stack[-1]
    for dx, dy in steps:
        q = (x + dx, y + dy)
        if q in pixels and q not in seen:
            seen.add(q)
            walk.append(q)
            stack.append((q, iter([(1, 0), (0, 1), (-1, 0), (0, -1)])))
            break
    else:
        stack.pop()
        if stack:
            walk.append(stack[-1][0])  # step back to the parent
if len(walk) > 1:
    walk.pop()  # the walk closes from its last pixel back to the first

with open(tour_out, "w") as f:
    json.dump({"cycles": [[list(p) for p in walk]]}, f)
