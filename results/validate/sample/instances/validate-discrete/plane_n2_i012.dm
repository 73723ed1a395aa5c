# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 2
e 0 1
p 0 0.10156035880239603 0.05780386230945416
p 1 0.8330903993426487 0.06854217075293971
