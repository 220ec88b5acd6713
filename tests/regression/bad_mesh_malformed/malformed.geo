// Bad input: not gmsh's language.
Point(1) = {0, 0, 0};
Line(3) = {1, 2
