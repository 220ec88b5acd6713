// A block of hexahedra, [0, L] x [0, L] x [0, Hz], a quarter model with the
// symmetry planes x = 0 and y = 0. Physical groups follow meshes/README.md.

DefineConstant[
  L = {1.0, Name "Parameters/Side length"},
  Hz = {0.5, Name "Parameters/Height"},
  n = {4, Name "Parameters/Cells per side"},
  nz = {2, Name "Parameters/Cells across the height"}
];

Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, L, 0};
Point(4) = {0, L, 0};
Line(1) = {1, 2};   // y = 0
Line(2) = {2, 3};   // x = L
Line(3) = {3, 4};   // y = L
Line(4) = {4, 1};   // x = 0
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};

// out[0]: top, out[1]: volume, out[2..5]: the sides swept by lines 1..4
out[] = Extrude{0, 0, Hz}{ Surface{1}; Layers{nz}; Recombine; };

Physical Volume("body:block") = {out[1]};
Physical Surface("fixed") = {1};
Physical Surface("contact:block") = {out[0]};
Physical Surface("symmetry y") = {out[2]};
Physical Surface("symmetry x") = {out[5]};
