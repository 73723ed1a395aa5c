# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 3
d 3
e 0 1
e 1 2
p 0 2 0.5773502691896257
p 1 2 1.1547005383792515
p 2 2.5 1.443375672974064
