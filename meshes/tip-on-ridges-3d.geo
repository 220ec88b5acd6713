// A hemispherical tip (radius R, apex at z = ridge + gap) above a substrate
// with parallel cylindrical ridges along y (radius r, pitch p, height
// `ridge` above the base plane z = 0), a quarter model: the tip sits over
// the crest of the ridge at x = 0; x = 0 and y = 0 are symmetry planes.
// Tetrahedra, refined towards the contact point. The tip's equator plane is
// driven, the substrate's bottom fixed, its far sides free.
// Physical groups follow meshes/README.md.

SetFactory("OpenCASCADE");

DefineConstant[
  R = {1.0, Name "Parameters/Tip radius"},
  gap = {0.05, Name "Parameters/Gap at the apex"},
  r = {0.3, Name "Parameters/Ridge radius"},
  p = {0.8, Name "Parameters/Ridge pitch"},
  ridge = {0.15, Name "Parameters/Ridge height"},
  W = {2.4, Name "Parameters/Substrate half width"},
  H = {1.5, Name "Parameters/Substrate depth"},
  lcContact = {0.04, Name "Parameters/Mesh size at the contact"},
  zone = {0.3, Name "Parameters/Radius of the fine zone"},
  lcFar = {0.3, Name "Parameters/Mesh size away from the contact"}
];

zc = ridge + gap + R;
Sphere(1) = {0, 0, zc, R, -Pi/2, 0, Pi/2};   // the tip: x, y >= 0, z <= zc
Box(2) = {0, 0, -H, W, W, H};
n = Floor(W / p) + 1;
For i In {0 : n - 1}
  Cylinder(10 + i) = {i * p, 0, ridge - r, 0, W, 0, r};
EndFor
rough[] = BooleanUnion{ Volume{2}; Delete; }{ Volume{10 : 10 + n - 1}; Delete; };
Box(3) = {0, 0, -H, W, W, H + ridge + 1e-3};
substrate[] = BooleanIntersection{ Volume{rough[]}; Delete; }{ Volume{3}; Delete; };

e = 1e-6 * R;
symX[] = Surface In BoundingBox{-e, -e, -H - e, e, W + e, zc + e};
symY[] = Surface In BoundingBox{-e, -e, -H - e, W + e, e, zc + e};
driven[] = Surface In BoundingBox{-e, -e, zc - e, R + e, R + e, zc + e};
fixed[] = Surface In BoundingBox{-e, -e, -H - e, W + e, W + e, -H + e};
farX[] = Surface In BoundingBox{W - e, -e, -H - e, W + e, W + e, ridge + e};
farY[] = Surface In BoundingBox{-e, W - e, -H - e, W + e, W + e, ridge + e};
tip[] = Abs(Boundary{ Volume{1}; });
tip[] -= {symX[], symY[], driven[]};
top[] = Abs(Boundary{ Volume{substrate[]}; });
top[] -= {symX[], symY[], fixed[], farX[], farY[]};
apex[] = Point In BoundingBox{-e, -e, ridge + gap - e, e, e, ridge + gap + e};
crest[] = Point In BoundingBox{-e, -e, ridge - e, e, e, ridge + e};

Field[1] = Distance;
Field[1].PointsList = {apex[], crest[]};
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g, Max(%g, %g + 0.35 * (F1 - %g)))", lcFar, lcContact, lcContact, zone);
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Volume("body:tip") = {1};
Physical Volume("body:substrate") = {substrate[]};
Physical Surface("symmetry x") = {symX[]};
Physical Surface("symmetry y") = {symY[]};
Physical Surface("driven") = {driven[]};
Physical Surface("fixed") = {fixed[]};
Physical Surface("contact:tip") = {tip[]};
Physical Surface("contact:substrate") = {top[]};
Physical Point("apex") = {apex[]};
Physical Point("lower apex") = {crest[]};
