// A quarter of a hemisphere (radius R, apex at z = gap) above a block
// [0, W] x [0, W] x [-H, 0], tetrahedra, refined towards the contact point.
// The planes x = 0 and y = 0 are symmetry planes; the hemisphere's flat top
// (z = gap + R) is driven, the block's bottom fixed.
// Physical groups follow meshes/README.md.

SetFactory("OpenCASCADE");

DefineConstant[
  R = {1.0, Name "Parameters/Sphere radius"},
  gap = {0.05, Name "Parameters/Gap at the apex"},
  W = {1.5, Name "Parameters/Block width"},
  H = {1.0, Name "Parameters/Block depth"},
  lc = {0.35, Name "Parameters/Mesh size away from the contact"},
  lcContact = {0.12, Name "Parameters/Mesh size at the contact"}
];

zc = gap + R;
Sphere(1) = {0, 0, zc, R, -Pi/2, 0, Pi/2};   // x >= 0, y >= 0, z <= zc
Box(2) = {0, 0, -H, W, W, H};

e = 1e-6 * R;
symX[] = Surface In BoundingBox{-e, -e, -H - e, e, W + e, zc + e};
symY[] = Surface In BoundingBox{-e, -e, -H - e, W + e, e, zc + e};
driven[] = Surface In BoundingBox{-e, -e, zc - e, R + e, R + e, zc + e};
fixed[] = Surface In BoundingBox{-e, -e, -H - e, W + e, W + e, -H + e};
top[] = Surface In BoundingBox{-e, -e, -e, W + e, W + e, e};
curved[] = Abs(Boundary{ Volume{1}; });
curved[] -= {symX[], symY[], driven[]};

// Mesh size: lcContact at the apex and the block corner below it, growing to lc.
tips[] = Point In BoundingBox{-e, -e, -e, e, e, gap + e};
Field[1] = Distance;
Field[1].PointsList = {tips[]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lcContact;
Field[2].SizeMax = lc;
Field[2].DistMin = 0.1 * R;
Field[2].DistMax = R;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Volume("body:sphere") = {1};
Physical Volume("body:substrate") = {2};
Physical Surface("symmetry x") = {symX[]};
Physical Surface("symmetry y") = {symY[]};
Physical Surface("driven") = {driven[]};
Physical Surface("fixed") = {fixed[]};
Physical Surface("contact:sphere") = {curved[]};
Physical Surface("contact:substrate") = {top[]};
