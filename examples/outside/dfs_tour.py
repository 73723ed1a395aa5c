#!/usr/bin/env python3
"""A minimal outside algorithm for mowmill: walk the depth-first-search tree of the pixels (or
of the vertices) there and back, a milling tour of length 2(N - 1) of a connected instance.

Usage: dfs_tour.py INSTANCE TOUR_OUT.json  (mowmill fills in {instance} and {tour_out}).
A grid region comes as a .grid file and its tour is a list of [x, y] pixels; a discrete
instance comes as a .dm file ('discrete N', edges 'e a b') and its tour is a list of vertices
(in {"model": "discrete", "cycles": ...}).
"""
import json
import sys

instance, tour_out = sys.argv[1], sys.argv[2]


def dfs_walk(start, neighbours):
    """The DFS tree from start walked there and back, as a closed walk (last step implied)."""
    walk, seen = [start], {start}
    stack = [(start, iter(neighbours(start)))]
    while stack:
        node, rest = stack[-1]
        for q in rest:
            if q not in seen:
                seen.add(q)
                walk.append(q)
                stack.append((q, iter(neighbours(q))))
                break
        else:
            stack.pop()
            if stack:
                walk.append(stack[-1][0])  # step back to the parent
    if len(walk) > 1:
        walk.pop()  # the walk closes from its last node back to the first
    return walk


if instance.endswith(".dm"):
    adjacent = {}
    for line in open(instance):
        words = line.split()
        if words and words[0] == "discrete":
            adjacent = {v: [] for v in range(int(words[1]))}
        elif words and words[0] == "e":
            a, b = int(words[1]), int(words[2])
            adjacent[a].append(b)
            adjacent[b].append(a)
    tour = {"model": "discrete", "cycles": [dfs_walk(0, lambda v: adjacent[v])]}
else:
    rows = [line.rstrip("\r\n") for line in open(instance) if not line.startswith(";")]
    # The first row is the highest y, the last row is y = 0; '#' is a pixel.
    pixels = {(x, len(rows) - 1 - i) for i, row in enumerate(rows) for x, c in enumerate(row) if c == "#"}
    steps = [(1, 0), (0, 1), (-1, 0), (0, -1)]
    walk = dfs_walk(min(pixels), lambda p: [(p[0] + dx, p[1] + dy) for dx, dy in steps
                                            if (p[0] + dx, p[1] + dy) in pixels])
    tour = {"cycles": [[list(p) for p in walk]]}

with open(tour_out, "w") as f:
    json.dump(tour, f)
