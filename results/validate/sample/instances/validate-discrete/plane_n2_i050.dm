# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, 'p v x y [z]' coordinates, 'd D' directions
discrete 2
e 0 1
p 0 0.18006228813841468 0.13316918593108393
p 1 0.9140931565068124 0.1574728789228238
