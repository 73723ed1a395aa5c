# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 39
e 0 1
e 1 2
e 2 3
e 2 15
e 3 4
e 4 5
e 5 6
e 6 7
e 6 19
e 7 8
e 8 9
e 9 10
e 10 11
e 10 23
e 11 12
e 13 14
e 14 15
e 15 16
e 16 17
e 16 29
e 17 18
e 18 19
e 19 20
e 20 21
e 20 33
e 21 22
e 22 23
e 23 24
e 24 25
e 24 37
e 26 27
e 27 28
e 28 29
e 29 30
e 30 31
e 31 32
e 32 33
e 33 34
e 34 35
e 35 36
e 36 37
e 37 38
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
c 27 26 28
c 28 27 29
c 29 28 30
c 30 29 31
c 31 30 32
c 32 31 33
c 33 32 34
c 34 33 35
c 35 34 36
c 36 35 37
c 37 36 38
