// A flat punch over a half-space, 2D: axisymmetric (a cylindrical punch of
// radius a, x = radius) or plane strain (a strip punch of half-width a; x = 0
// is a symmetry line). The punch [0, a] x [gap, gap + Hp] faces the block
// [0, W] x [-H, 0] across the gap; its flat face is the interacting surface,
// its sides are not. The corner (a, gap) and the point under it are resolved:
// cells of lcCorner within cornerZone of them, lc along the face and the top
// of the block under the face, growing to lcFar away.
// Free quadrilateral mesh (Frontal-Delaunay triangles recombined by blossom).
// Usually the punch is rigid (Bodies/punch/Rigid = true in the deck).
// Physical groups follow meshes/README.md; override the constants from the
// deck (Geometry/Mesh Numbers) or with gmsh -setnumber.

DefineConstant[
  a = {1.0, Name "Parameters/Punch radius (half-width) a"},
  Hp = {0.5, Name "Parameters/Punch height"},
  gap = {0.02 / 15^(1/6), Name "Parameters/Gap at the face (r_S0 at gammaL = 50)"},
  W = {8.0, Name "Parameters/Block half-width"},
  H = {8.0, Name "Parameters/Block depth"},
  lc = {0.02, Name "Parameters/Cell size along the face"},
  lcCorner = {0.002, Name "Parameters/Cell size at the corner"},
  cornerZone = {0.05, Name "Parameters/Extent of the corner cells"},
  lcFar = {0.5, Name "Parameters/Cell size far from the face"}
];

// Punch.
Point(1) = {0, gap, 0};        // centre of the face (apex)
Point(2) = {a, gap, 0};        // corner
Point(3) = {a, gap + Hp, 0};
Point(4) = {0, gap + Hp, 0};
Line(1) = {1, 2};              // face: the interacting surface
Line(2) = {2, 3};
Line(3) = {3, 4};              // top, driven
Line(4) = {4, 1};              // axis
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// Block.
Point(11) = {0, 0, 0};         // under the centre (lower apex)
Point(12) = {a, 0, 0};         // under the corner
Point(13) = {W, 0, 0};
Point(14) = {W, -H, 0};
Point(15) = {0, -H, 0};
Line(11) = {11, 12};           // top: the interacting surface
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};           // bottom, fixed
Line(15) = {15, 11};           // axis
Curve Loop(2) = {11, 12, 13, 14, 15};
Plane Surface(2) = {2};

// Sizes: lcCorner at the corner and under it, lc along the face and the top
// of the block under it, lcFar far away.
Field[1] = Distance;
Field[1].PointsList = {2, 12};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lcCorner;
Field[2].SizeMax = lcFar;
Field[2].DistMin = cornerZone;
Field[2].DistMax = cornerZone + 10 * (lc - lcCorner) + 20 * (lcFar - lc);
Field[3] = Distance;
Field[3].CurvesList = {1, 11};
Field[3].NumPointsPerCurve = 200;
Field[4] = Threshold;
Field[4].InField = 3;
Field[4].SizeMin = lc;
Field[4].SizeMax = lcFar;
Field[4].DistMin = 4 * lc;
Field[4].DistMax = 4 * lc + 10 * (lcFar - lc);
Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;                // Frontal-Delaunay
Mesh.RecombinationAlgorithm = 1;   // blossom
Recombine Surface{1, 2};

Physical Surface("body:punch") = {1};
Physical Surface("body:half-space") = {2};
Physical Curve("axis") = {4, 15};
Physical Curve("driven") = {3};
Physical Curve("fixed") = {14};
Physical Curve("contact:punch") = {1};
Physical Curve("contact:half-space") = {11, 12};
Physical Point("apex") = {1};
Physical Point("lower apex") = {11};
