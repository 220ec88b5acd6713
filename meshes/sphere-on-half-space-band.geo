// The paper's benchmark (a sphere of radius R above a half-space block, in the
// meridian half-plane: x = radius, y = axis) as a free quadrilateral mesh
// whose finest cells, of size lc, lie only in a band under the two
// interacting surfaces within the radius zone R of the axis. Away from the band
// the cells grow by about `growth` of the distance, to lcFar. For contacts
// whose cohesive zone is much smaller than the contact (large Tabor mu) this
// resolves the contact edge with far fewer cells than the graded block of
// sphere-on-half-space.geo, whose fine columns reach through the whole depth.
// Physical groups follow meshes/README.md, the same names as the built-in
// mesh's; override the constants from the deck (Geometry/Mesh Numbers).

DefineConstant[
  R = {1.0, Name "Parameters/Sphere radius R0"},
  gap = {0.02 / 15^(1/6), Name "Parameters/Gap at the apex (r_S0 at gammaL = 50)"},
  W = {8.0, Name "Parameters/Half-space width"},
  H = {8.0, Name "Parameters/Half-space depth"},
  zone = {0.5, Name "Parameters/Radius of the fine band around the axis (in R0, < 1)"},
  lc = {0.01, Name "Parameters/Cell size in the band"},
  band = {4, Name "Parameters/Band depth in cells of size lc"},
  growth = {0.2, Name "Parameters/Growth of the cell size per unit distance from the band"},
  lcFar = {0.5, Name "Parameters/Largest cell size"}
];

If (!(R > 0 && gap > 0 && H > 0 && zone > 0 && zone < 1 && zone * R < W && lc > 0 && lc < zone * R &&
      band >= 0 && growth > 0 && lcFar >= lc))
  Error("sphere-on-half-space-band.geo: need R, gap, H > 0, 0 < zone < 1, zone R < W, 0 < lc < zone R, band >= 0, growth > 0 and lcFar >= lc");
  Abort;
EndIf

// Lower quarter disc (the upper half carries no load and is left out); its arc
// is cut where the band ends, at the polar angle whose radius is zone R.
theta = Asin(zone);
Point(1) = {0, gap + R, 0};                                    // centre
Point(2) = {0, gap, 0};                                        // apex
Point(3) = {R * Sin(theta), gap + R - R * Cos(theta), 0};     // end of the band
Point(4) = {R, gap + R, 0};                                    // equator end
Line(1) = {1, 2};                                              // axis
Circle(2) = {2, 1, 3};                                         // interacting, in the band
Circle(3) = {3, 1, 4};                                         // interacting, outside the band
Line(4) = {4, 1};                                              // equator, driven
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// Half-space block [0, W] x [-H, 0], its top cut at x = zone R.
Point(11) = {0, 0, 0};
Point(12) = {zone * R, 0, 0};
Point(13) = {W, 0, 0};
Point(14) = {W, -H, 0};
Point(15) = {0, -H, 0};
Line(11) = {11, 12};                                           // top, in the band
Line(12) = {12, 13};                                           // top, outside the band
Line(13) = {13, 14};                                           // side
Line(14) = {14, 15};                                           // bottom, fixed
Line(15) = {15, 11};                                           // axis
Curve Loop(2) = {11, 12, 13, 14, 15};
Plane Surface(2) = {2};

Field[1] = Distance;
Field[1].CurvesList = {2, 11};
Field[1].NumPointsPerCurve = Ceil(4 * zone * R / lc) + 10;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lc;
Field[2].SizeMax = lcFar;
Field[2].DistMin = band * lc;
Field[2].DistMax = band * lc + (lcFar - lc) / growth;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;                // Frontal-Delaunay (gmsh 4.8's quad variant, 8, crashes on such fields)
Mesh.RecombinationAlgorithm = 1;   // blossom
Recombine Surface{1, 2};

Physical Surface("body:sphere") = {1};
Physical Surface("body:half-space") = {2};
Physical Curve("axis") = {1, 15};
Physical Curve("driven") = {4};
Physical Curve("fixed") = {14};
Physical Curve("contact:sphere") = {2, 3};
Physical Curve("contact:half-space") = {11, 12};
Physical Point("apex") = {2};
Physical Point("lower apex") = {11};
