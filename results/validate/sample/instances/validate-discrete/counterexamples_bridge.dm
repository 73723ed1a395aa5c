# Theorem 4.2's t + 2c - 2 fails in discrete milling (docs/discrete.md, Findings 3): straight paths 0..4 and 5..9
# joined by the bridge 2-7, collinear with nothing; the star cover has t = 8, c = 2, and every tour has at least 12 turns.
discrete 10
e 0 1
e 1 2
e 2 3
e 3 4
e 5 6
e 6 7
e 7 8
e 8 9
e 2 7
c 1 0 2
c 2 1 3
c 3 2 4
c 6 5 7
c 7 6 8
c 8 7 9
