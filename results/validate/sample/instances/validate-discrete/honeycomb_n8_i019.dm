# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 8
d 3
e 0 3
e 1 2
e 2 3
e 2 6
e 3 4
e 5 6
e 6 7
p 0 2 0.5773502691896257
p 1 1 1.1547005383792515
p 2 1.5 1.443375672974064
p 3 2 1.1547005383792515
p 4 2.5 1.443375672974064
p 5 1 2.309401076758503
p 6 1.5 2.0207259421636903
p 7 2 2.309401076758503
