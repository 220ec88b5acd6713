// The paper's benchmark as the built-in generator makes it (Geometry/Type =
// "sphere on half-space", packages/mesh/src/Benchmark.cpp), node for node: a
// sphere of radius R above a half-space block, in the meridian half-plane
// (x = radius, y = axis; a cylinder on a half-space in plane strain). The
// sphere's apex sits gap above the block's top y = 0. With the apex node sets
// cgcm measures u from where the apexes are r_S0 apart, whatever the gap.
// Physical groups follow meshes/README.md; override the constants from the
// deck (Geometry/Mesh Numbers) or with gmsh -setnumber.

DefineConstant[
  R = {1.0, Name "Parameters/Sphere radius R0"},
  gap = {0.02 / 15^(1/6), Name "Parameters/Gap at the apex (r_S0 at gammaL = 50)"},
  W = {8.0, Name "Parameters/Half-space width"},
  H = {8.0, Name "Parameters/Half-space depth"},
  zone = {0.5, Name "Parameters/Contact zone size (in R0)"},
  level = {0, Name "Parameters/Refinement level (0 .. 6, each halves every cell)"}
];


qR = R; qCy = R + gap; qSy = -1; qFine = 0.8 * zone; qLevel = level;
Include "include/quarter-disc.geo";
bW = W; bH = H; bTop = 0; bFine = zone * R; bLevel = level;
Include "include/half-space-block.geo";

Physical Surface("body:sphere") = {qSurfaces[]};
Physical Surface("body:half-space") = {bSurface};
Physical Curve("axis") = {qAxis[], bAxis[]};
Physical Curve("driven") = {qEquator[]};
Physical Curve("fixed") = {bBottom[]};
Physical Curve("contact:sphere") = {qArc[]};
Physical Curve("contact:half-space") = {bTopEdge[]};
Physical Point("apex") = {qApex};
Physical Point("lower apex") = {bApex};
