// The benchmark of meshes/sphere-on-half-space.geo in 3D, as a quarter model:
// the lower hemisphere (radius R, apex at z = gap) above a block
// [0, W] x [0, W] x [-H, 0], tetrahedra, refined towards the contact point.
// The planes x = 0 and y = 0 are symmetry planes; the hemisphere's equator
// plane (z = gap + R) is driven, the block's bottom fixed, its far sides free
// (as in the axisymmetric benchmark). `apex` and `lower apex` set u = 0 where
// the undeformed surfaces are r_S0 apart, whatever `gap` is.
// Physical groups follow meshes/README.md.

SetFactory("OpenCASCADE");

DefineConstant[
  R = {1.0, Name "Parameters/Sphere radius"},
  gap = {0.05, Name "Parameters/Gap at the apex"},
  W = {8.0, Name "Parameters/Block width"},
  H = {8.0, Name "Parameters/Block depth"},
  lcContact = {0.04, Name "Parameters/Mesh size in the contact zone"},
  zone = {0.35, Name "Parameters/Radius of the contact zone"},
  lcSphere = {0.25, Name "Parameters/Mesh size on the rest of the sphere"},
  lcFar = {2.0, Name "Parameters/Mesh size far from the contact"}
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
apex[] = Point In BoundingBox{-e, -e, gap - e, e, e, gap + e};
lowerApex[] = Point In BoundingBox{-e, -e, -e, e, e, e};

// Mesh size: lcContact within `zone` of the axis near the contact, growing to
// lcSphere on the sphere and lcFar in the block.
Field[1] = Cylinder;
Field[1].Radius = zone;
Field[1].VIn = lcContact;
Field[1].VOut = 1e22;
Field[1].XAxis = 0; Field[1].YAxis = 0; Field[1].ZAxis = 0.4 * R;
Field[1].XCenter = 0; Field[1].YCenter = 0; Field[1].ZCenter = gap / 2;
Field[2] = Distance;
Field[2].PointsList = {apex[], lowerApex[]};
Field[3] = MathEval;
Field[3].F = Sprintf("Min(%g, Max(%g, %g + 0.35 * (F2 - %g)))", lcFar, lcContact, lcContact, zone);
Field[4] = Box;
Field[4].VIn = lcSphere; Field[4].VOut = 1e22;
Field[4].XMin = -e; Field[4].XMax = R + e; Field[4].YMin = -e; Field[4].YMax = R + e;
Field[4].ZMin = gap - e; Field[4].ZMax = zc + e;
Field[5] = Min;
Field[5].FieldsList = {1, 3, 4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Volume("body:sphere") = {1};
Physical Volume("body:half-space") = {2};
Physical Surface("symmetry x") = {symX[]};
Physical Surface("symmetry y") = {symY[]};
Physical Surface("driven") = {driven[]};
Physical Surface("fixed") = {fixed[]};
Physical Surface("contact:sphere") = {curved[]};
Physical Surface("contact:half-space") = {top[]};
Physical Point("apex") = {apex[]};
Physical Point("lower apex") = {lowerApex[]};
