# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 2
e 0 1
p 0 -0.05595471249469868 0.05775779033280224
p 1 1.1588785583990355 -0.031918447017549
