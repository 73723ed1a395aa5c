# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 2
e 0 1
p 0 0.11074330551120237 0.12682263901888297
p 1 0.9606780680471643 0.09038247481165076
