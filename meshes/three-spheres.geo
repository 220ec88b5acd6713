// Three equal hemispheres (radius R) in a row along x above a substrate,
// drawn for x >= 0, y >= 0: the middle hemisphere's quarter, one outer
// hemisphere's half (centre x = d) and the substrate's quarter
// [0, W] x [0, W/2] x [-H, 0]. The deck mirrors it in x = 0 and y = 0
// (Geometry/Mirror Planes = {x, y}): the whole model, and the two outer
// spheres exact mirror images. Each hemisphere is held at its equator plane
// (z = gap + R, "fixed"); the substrate's bottom is "driven". Used without
// mirroring, "symmetry x" and "symmetry y" make it a quarter model.
// Physical groups follow meshes/README.md.

SetFactory("OpenCASCADE");

DefineConstant[
  R = {1.0, Name "Parameters/Sphere radius"},
  d = {2.5, Name "Parameters/Distance between the sphere centres"},
  gap = {0.05, Name "Parameters/Gap at the apexes"},
  W = {5.0, Name "Parameters/Substrate half width (x)"},
  H = {2.5, Name "Parameters/Substrate depth"},
  lcContact = {0.06, Name "Parameters/Mesh size at the contacts"},
  zone = {0.4, Name "Parameters/Radius of the fine zones"},
  lcSphere = {0.2, Name "Parameters/Mesh size on the rest of the spheres"},
  lcFar = {1.0, Name "Parameters/Mesh size far from the contacts"}
];

zc = gap + R;
Sphere(1) = {0, 0, zc, R, -Pi/2, 0, Pi/2};   // middle: x >= 0, y >= 0, z <= zc
Sphere(2) = {d, 0, zc, R, -Pi/2, 0, Pi};     // outer: y >= 0, z <= zc
Box(3) = {0, 0, -H, W, W / 2, H};

e = 1e-6 * R;
symX[] = Surface In BoundingBox{-e, -e, -H - e, e, W + e, zc + e};
symY[] = Surface In BoundingBox{-e, -e, -H - e, W + e, e, zc + e};
fixed[] = Surface In BoundingBox{-e, -e, zc - e, W + e, W + e, zc + e};
driven[] = Surface In BoundingBox{-e, -e, -H - e, W + e, W + e, -H + e};
top[] = Surface In BoundingBox{-e, -e, -e, W + e, W + e, e};
middle[] = Abs(Boundary{ Volume{1}; });
middle[] -= {symX[], symY[], fixed[]};
outer[] = Abs(Boundary{ Volume{2}; });
outer[] -= {symY[], fixed[]};
tips[] = Point In BoundingBox{-e, -e, -e, d + e, e, gap + e};

// Mesh size: lcContact within `zone` of the apexes and the points below them,
// growing to lcSphere on the spheres and lcFar in the substrate.
Field[1] = Distance;
Field[1].PointsList = {tips[]};
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g, Max(%g, %g + 0.35 * (F1 - %g)))", lcFar, lcContact, lcContact, zone);
Field[3] = Box;
Field[3].VIn = lcSphere; Field[3].VOut = 1e22;
Field[3].XMin = -e; Field[3].XMax = d + R + e; Field[3].YMin = -e; Field[3].YMax = R + e;
Field[3].ZMin = gap - e; Field[3].ZMax = zc + e;
Field[4] = Min;
Field[4].FieldsList = {2, 3};
Background Field = 4;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Volume("body:middle sphere") = {1};
Physical Volume("body:outer sphere") = {2};
Physical Volume("body:substrate") = {3};
Physical Surface("symmetry x") = {symX[]};
Physical Surface("symmetry y") = {symY[]};
Physical Surface("fixed") = {fixed[]};
Physical Surface("driven") = {driven[]};
Physical Surface("contact:middle sphere") = {middle[]};
Physical Surface("contact:outer sphere") = {outer[]};
Physical Surface("contact:substrate") = {top[]};
