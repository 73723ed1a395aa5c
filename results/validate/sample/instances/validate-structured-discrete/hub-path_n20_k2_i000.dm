# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 22
e 0 1
e 1 2
e 1 20
e 2 3
e 2 20
e 3 4
e 3 20
e 4 5
e 4 20
e 5 6
e 5 20
e 6 7
e 6 20
e 7 8
e 7 20
e 8 9
e 8 20
e 9 10
e 9 20
e 10 11
e 10 21
e 11 12
e 11 21
e 12 13
e 12 21
e 13 14
e 13 21
e 14 15
e 14 21
e 15 16
e 15 21
e 16 17
e 16 21
e 17 18
e 17 21
e 18 19
e 18 21
c 1 0 2
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
