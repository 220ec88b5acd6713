// A cylinder on a flat elastic layer, plane strain (Problem/Formulation =
// "plane strain"): the half cylinder x >= 0 of radius R (x = 0 is a symmetry
// line) with its apex gap above a layer of width W and thickness T on a rigid
// base. Unlike sphere-on-half-space.geo this is a free mesh: gmsh's
// quadrilaterals (Frontal-Delaunay triangles recombined by blossom), of size lc within
// zone of the contact and growing to lcFar away from it.
// Physical groups follow meshes/README.md; override the constants from the
// deck (Geometry/Mesh Numbers) or with gmsh -setnumber.

DefineConstant[
  R = {1.0, Name "Parameters/Cylinder radius R0"},
  gap = {0.02 / 15^(1/6), Name "Parameters/Gap at the apex (r_S0 at gammaL = 50)"},
  W = {4.0, Name "Parameters/Layer half-width"},
  T = {1.0, Name "Parameters/Layer thickness"},
  lc = {0.025, Name "Parameters/Cell size at the contact"},
  lcFar = {0.25, Name "Parameters/Cell size far from the contact"},
  zone = {0.3, Name "Parameters/Extent of the finest cells around the apex"}
];

// Half cylinder (lower quarter: the upper half carries no load and is left out).
Point(1) = {0, gap + R, 0};   // centre
Point(2) = {0, gap, 0};       // apex
Point(3) = {R, gap + R, 0};   // equator end
Line(1) = {1, 2};             // symmetry line
Circle(2) = {2, 1, 3};        // the interacting surface
Line(3) = {3, 1};             // equator, driven
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

// Layer [0, W] x [-T, 0].
Point(11) = {0, 0, 0};
Point(12) = {W, 0, 0};
Point(13) = {W, -T, 0};
Point(14) = {0, -T, 0};
Line(11) = {11, 12};          // top, the interacting surface
Line(12) = {12, 13};
Line(13) = {13, 14};          // base, fixed
Line(14) = {14, 11};          // symmetry line
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};

Field[1] = Distance;
Field[1].PointsList = {2, 11};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lc;
Field[2].SizeMax = lcFar;
Field[2].DistMin = zone;
Field[2].DistMax = 4 * zone + 10 * (lcFar - lc);
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;                // Frontal-Delaunay (gmsh 4.8's quad variant, 8, crashes here)
Mesh.RecombinationAlgorithm = 1;   // blossom
Recombine Surface{1, 2};

Physical Surface("body:cylinder") = {1};
Physical Surface("body:layer") = {2};
Physical Curve("axis") = {1, 14};
Physical Curve("driven") = {3};
Physical Curve("fixed") = {13};
Physical Curve("contact:cylinder") = {2};
Physical Curve("contact:layer") = {11};
Physical Point("apex") = {2};
Physical Point("lower apex") = {11};
