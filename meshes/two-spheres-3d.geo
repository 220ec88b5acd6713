// Two spheres in 3D, a quarter model: the upper sphere's lower hemisphere
// (radius R, apex at z = gap) above the lower sphere's upper hemisphere
// (radius R2, apex at z = 0), tetrahedra refined towards the contact point.
// The planes x = 0 and y = 0 are symmetry planes; the upper equator plane is
// driven, the lower one fixed. `apex` and `lower apex` set u = 0 where the
// undeformed surfaces are r_S0 apart. Physical groups follow meshes/README.md.

SetFactory("OpenCASCADE");

DefineConstant[
  R = {1.0, Name "Parameters/Upper sphere radius"},
  R2 = {1.0, Name "Parameters/Lower sphere radius"},
  gap = {0.05, Name "Parameters/Gap at the apexes"},
  lcContact = {0.04, Name "Parameters/Mesh size in the contact zone"},
  zone = {0.35, Name "Parameters/Radius of the contact zone"},
  lcFar = {0.25, Name "Parameters/Mesh size on the rest of the spheres"}
];

zc = gap + R;
Sphere(1) = {0, 0, zc, R, -Pi/2, 0, Pi/2};    // x, y >= 0, z <= zc
Sphere(2) = {0, 0, -R2, R2, 0, Pi/2, Pi/2};   // x, y >= 0, z >= -R2

e = 1e-6 * R;
big = 2 * (R + R2 + gap);
symX[] = Surface In BoundingBox{-e, -e, -big, e, big, big};
symY[] = Surface In BoundingBox{-e, -e, -big, big, e, big};
driven[] = Surface In BoundingBox{-e, -e, zc - e, R + e, R + e, zc + e};
fixed[] = Surface In BoundingBox{-e, -e, -R2 - e, R2 + e, R2 + e, -R2 + e};
upper[] = Abs(Boundary{ Volume{1}; });
upper[] -= {symX[], symY[], driven[]};
lower[] = Abs(Boundary{ Volume{2}; });
lower[] -= {symX[], symY[], fixed[]};
apex[] = Point In BoundingBox{-e, -e, gap - e, e, e, gap + e};
lowerApex[] = Point In BoundingBox{-e, -e, -e, e, e, e};

Field[1] = Distance;
Field[1].PointsList = {apex[], lowerApex[]};
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g, Max(%g, %g + 0.35 * (F1 - %g)))", lcFar, lcContact, lcContact, zone);
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Volume("body:sphere") = {1};
Physical Volume("body:second sphere") = {2};
Physical Surface("symmetry x") = {symX[]};
Physical Surface("symmetry y") = {symY[]};
Physical Surface("driven") = {driven[]};
Physical Surface("fixed") = {fixed[]};
Physical Surface("contact:sphere") = {upper[]};
Physical Surface("contact:second sphere") = {lower[]};
Physical Point("apex") = {apex[]};
Physical Point("lower apex") = {lowerApex[]};
