# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 6
d 3
e 0 1
e 1 4
e 2 3
e 3 4
e 4 5
p 0 1.5 0.28867513459481287
p 1 2 0.5773502691896257
p 2 1 1.1547005383792515
p 3 1.5 1.443375672974064
p 4 2 1.1547005383792515
p 5 2.5 1.443375672974064
