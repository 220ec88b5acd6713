// A thin strip on a substrate, plane strain (Problem/Formulation = "plane
// strain"), peeled at the angle theta (degrees, between the peeled arm and
// the substrate). Drawn first with the substrate's top on y = 0: the bonded
// part [xf, L] x [gap, gap + h] lies on it across the gap (r_S0 of the deck's
// gammaL, where the bodies are at rest); at the front x = xf the strip bends
// up by theta over an arc of radius R (its underside; R - h its top), so that
// the underside leaves the substrate tangentially as at a steady front, and
// goes on as a straight arm of length a. Then the whole is turned by
// theta - 90 degrees about the origin, so that the arm points along +y: a
// vertical pull on its end ("driven", Geometry/Drive Direction = up, x free)
// pulls along the arm at the angle theta to the substrate, whatever the
// front does. The strip's far end is held ("fixed", with the substrate's
// base): a Lennard-Jones bond to a flat substrate carries no shear, so the
// bonded part carries the pull's part along the substrate. The underside of
// the bonded part is the interacting surface, along all of it because the
// front runs along all of it; the bend and the arm do not interact, so that
// the start is at rest and the front a crack tip. Cells of lc along the
// strip, nh through it; the substrate is one cell deep and meant to be rigid
// (Bodies/substrate/Rigid). With width > 0 both are extruded across the
// width into a tape and turned so that the pull is along +z
// (Problem/Formulation = 3D; the tape spans y in [-width, 0], nz cells): y = 0
// is a symmetry plane (P is the force on a tape 2 width wide) and the face
// y = -width is held in y too (edges = 1: plane strain, the 2D strip's
// check) or free (edges = 0: the tape's free edge). Physical groups
// follow meshes/README.md; override the constants from the deck
// (Geometry/Mesh Numbers) or with gmsh -setnumber.

DefineConstant[
  theta = {90, Name "Parameters/Peel angle (degrees, 1 .. 170)"},
  L = {40.0, Name "Parameters/Far end of the strip (x)"},
  xf = {6.0, Name "Parameters/Front at the start (x)"},
  R = {5.0, Name "Parameters/Radius of the bend at the front (underside)"},
  a = {5.0, Name "Parameters/Length of the straight arm"},
  h = {1.0, Name "Parameters/Strip thickness"},
  gap = {0.05 / 15^(1/6), Name "Parameters/Gap (r_S0 at gammaL = 20)"},
  lc = {0.1, Name "Parameters/Cell size along the strip"},
  nh = {2, Name "Parameters/Cells through the strip"},
  margin = {2.0, Name "Parameters/Substrate beyond the strip"},
  Hs = {0.5, Name "Parameters/Substrate thickness"},
  width = {0, Name "Parameters/3D: half the tape's width, y = 0 its symmetry plane (0: the 2D strip)"},
  nz = {2, Name "Parameters/3D: cells across the width"},
  edges = {1, Name "Parameters/3D: 1: both side faces held across the width (plane strain); 0: the face y = -width free"}
];

If (theta < 1 || theta > 170 || R <= h || xf <= 0 || L <= xf || width < 0 || nz < 1 || (edges != 0 && edges != 1))
  Error("peel-strip.geo: needs 1 <= theta <= 170 degrees, R > h, 0 < xf < L, width >= 0, nz >= 1, edges 0 or 1");
  Abort;
EndIf

t = theta * Pi / 180;
nx = Ceil((L - xf) / lc);
nr = Ceil(R * t / lc);
na = Ceil(a / lc);

// Bonded part.
Point(1) = {xf, gap, 0};                    // the front
Point(2) = {L, gap, 0};
Point(3) = {L, gap + h, 0};
Point(4) = {xf, gap + h, 0};
Line(1) = {1, 2};                           // underside
Line(2) = {2, 3};                           // far end, held
Line(3) = {3, 4};                           // top
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// Bend: arcs about (xf, gap + R) from the front to the arm's root.
Point(5) = {xf, gap + R, 0};
Point(6) = {xf - R * Sin(t), gap + R - R * Cos(t), 0};
Point(7) = {xf - (R - h) * Sin(t), gap + R - (R - h) * Cos(t), 0};
Circle(5) = {1, 5, 6};                      // underside
Line(6) = {6, 7};
Circle(7) = {7, 5, 4};                      // top
Curve Loop(2) = {5, 6, 7, 4};
Plane Surface(2) = {2};

// Arm along (-cos t, sin t); its end square to it.
Point(8) = {xf - R * Sin(t) - a * Cos(t), gap + R - R * Cos(t) + a * Sin(t), 0};
Point(9) = {xf - (R - h) * Sin(t) - a * Cos(t), gap + R - (R - h) * Cos(t) + a * Sin(t), 0};
Line(8) = {6, 8};                           // underside
Line(9) = {8, 9};                           // end, driven
Line(10) = {9, 7};                          // top
Curve Loop(3) = {8, 9, 10, -6};
Plane Surface(3) = {3};

Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{5, 7} = nr + 1;
Transfinite Curve{8, 10} = na + 1;
Transfinite Curve{2, 4, 6, 9} = nh + 1;
Transfinite Surface{1, 2, 3};

// Substrate: cells of lc along it, under the bonded part node for node with the strip's.
x0 = xf - R - a - margin;
Point(11) = {x0, 0, 0};
Point(12) = {xf, 0, 0};
Point(13) = {L, 0, 0};
Point(14) = {L + margin, 0, 0};
Point(15) = {L + margin, -Hs, 0};
Point(16) = {L, -Hs, 0};
Point(17) = {xf, -Hs, 0};
Point(18) = {x0, -Hs, 0};
Line(11) = {11, 12};                        // top: the interacting surface (11, 12, 13)
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};
Line(15) = {15, 16};                        // base, fixed (15, 16, 17)
Line(16) = {16, 17};
Line(17) = {17, 18};
Line(18) = {18, 11};
Line(19) = {12, 17};
Line(20) = {13, 16};
Curve Loop(11) = {11, 19, 17, 18};
Plane Surface(11) = {11};
Curve Loop(12) = {12, 20, 16, -19};
Plane Surface(12) = {12};
Curve Loop(13) = {13, 14, 15, -20};
Plane Surface(13) = {13};
Transfinite Curve{12, 16} = nx + 1;
Transfinite Curve{11, 17} = Ceil((xf - x0) / lc) + 1;
Transfinite Curve{13, 15} = Ceil(margin / lc) + 1;
Transfinite Curve{14, 18, 19, 20} = 2;
Transfinite Surface{11, 12, 13};

Recombine Surface{1, 2, 3, 11, 12, 13};
Rotate {{0, 0, 1}, {0, 0, 0}, t - Pi / 2} { Surface{1, 2, 3, 11, 12, 13}; }

If (width == 0)
  Physical Surface("body:strip") = {1, 2, 3};
  Physical Surface("body:substrate") = {11, 12, 13};
  Physical Curve("driven") = {9};
  Physical Curve("fixed") = {2, 15, 16, 17};
  Physical Curve("contact:strip") = {1};
  Physical Curve("contact:substrate") = {11, 12, 13};
Else
  // 3D: both bodies extruded across the width (each body in one command, so
  // that their shared faces are one). Per source surface Extrude lists its
  // far face, its volume, then the faces swept by its loop's curves in order.
  // first turned about x so that the pull is along +z, the vertical of 3D; the tape spans y in [-width, 0]
  Rotate {{1, 0, 0}, {0, 0, 0}, Pi / 2} { Surface{1, 2, 3, 11, 12, 13}; }
  st[] = Extrude {0, -width, 0} { Surface{1, 2, 3}; Layers{nz}; Recombine; };
  sb[] = Extrude {0, -width, 0} { Surface{11, 12, 13}; Layers{1}; Recombine; };
  Physical Volume("body:strip") = {st[1], st[7], st[13]};
  Physical Volume("body:substrate") = {sb[1], sb[7], sb[13]};
  Physical Surface("driven") = {st[15]};                       // from curve 9
  Physical Surface("fixed") = {st[3], sb[4], sb[10], sb[16]};  // curve 2; curves 17, 16, 15
  Physical Surface("contact:strip") = {st[2]};                 // curve 1
  Physical Surface("contact:substrate") = {sb[2], sb[8], sb[14]};
  If (edges == 1)
    Physical Surface("symmetry y") = {1, 2, 3, st[0], st[6], st[12]};
  Else
    Physical Surface("symmetry y") = {1, 2, 3};
  EndIf
EndIf
