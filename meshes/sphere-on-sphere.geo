// Two spheres as the built-in generator makes them (Geometry/Type = "sphere on
// sphere", packages/mesh/src/Benchmark.cpp), node for node: a sphere of
// radius R with its apex gap above the apex of a second sphere of radius R2,
// in the meridian half-plane (x = radius, y = axis; cylinders in plane
// strain). The upper sphere's equator is driven, the lower one's fixed.
// Physical groups follow meshes/README.md; override the constants from the
// deck (Geometry/Mesh Numbers) or with gmsh -setnumber.

DefineConstant[
  R = {1.0, Name "Parameters/Sphere radius R0"},
  R2 = {1.0, Name "Parameters/Second sphere radius"},
  gap = {0.02 / 15^(1/6), Name "Parameters/Gap at the apex (r_S0 at gammaL = 50)"},
  zone = {0.5, Name "Parameters/Contact zone size (in R0)"},
  level = {0, Name "Parameters/Refinement level (0 .. 6, each halves every cell)"}
];


qR = R; qCy = R + gap; qSy = -1; qFine = 0.8 * zone; qLevel = level;
Include "include/quarter-disc.geo";
upperSurfaces[] = qSurfaces[]; upperAxis[] = qAxis[]; upperEquator[] = qEquator[]; upperArc[] = qArc[];
upperApex = qApex;
qR = R2; qCy = -R2; qSy = 1; qFine = Min(0.8 * zone * R / R2, 0.69); qLevel = level;
Include "include/quarter-disc.geo";

Physical Surface("body:sphere") = {upperSurfaces[]};
Physical Surface("body:second sphere") = {qSurfaces[]};
Physical Curve("axis") = {upperAxis[], qAxis[]};
Physical Curve("driven") = {upperEquator[]};
Physical Curve("fixed") = {qEquator[]};
Physical Curve("contact:sphere") = {upperArc[]};
Physical Curve("contact:second sphere") = {qArc[]};
Physical Point("apex") = {upperApex};
Physical Point("lower apex") = {qApex};
