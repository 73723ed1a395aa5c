# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 2
e 0 1
p 0 -0.006803330060469648 0.028408284471822753
p 1 0.9236176762673161 0.05985546224796976
