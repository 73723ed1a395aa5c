# Theorem 5.1 with averaged rho, delta fails for the greedy star cover in index order (docs/discrete.md, Findings 2):
# hub 0 joined by unmatched edges to the 30 inner vertices of a straight path 1..32; the hub is the first rook.
discrete 33
e 1 2
e 2 3
e 3 4
e 4 5
e 5 6
e 6 7
e 7 8
e 8 9
e 9 10
e 10 11
e 11 12
e 12 13
e 13 14
e 14 15
e 15 16
e 16 17
e 17 18
e 18 19
e 19 20
e 20 21
e 21 22
e 22 23
e 23 24
e 24 25
e 25 26
e 26 27
e 27 28
e 28 29
e 29 30
e 30 31
e 31 32
e 0 2
e 0 3
e 0 4
e 0 5
e 0 6
e 0 7
e 0 8
e 0 9
e 0 10
e 0 11
e 0 12
e 0 13
e 0 14
e 0 15
e 0 16
e 0 17
e 0 18
e 0 19
e 0 20
e 0 21
e 0 22
e 0 23
e 0 24
e 0 25
e 0 26
e 0 27
e 0 28
e 0 29
e 0 30
e 0 31
c 2 1 3
c 3 2 4
c 4 3 5
c 5 4 6
c 6 5 7
c 7 6 8
c 8 7 9
c 9 8 10
c 10 9 11
c 11 10 12
c 12 11 13
c 13 12 14
c 14 13 15
c 15 14 16
c 16 15 17
c 17 16 18
c 18 17 19
c 19 18 20
c 20 19 21
c 21 20 22
c 22 21 23
c 23 22 24
c 24 23 25
c 25 24 26
c 26 25 27
c 27 26 28
c 28 27 29
c 29 28 30
c 30 29 31
c 31 30 32
