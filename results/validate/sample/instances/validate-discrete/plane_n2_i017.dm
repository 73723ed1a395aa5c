# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 2
e 0 1
p 0 -0.05826480565565504 -0.023531429744811573
p 1 1.100008331410022 -0.08858012887987542
