// Quarter disc (the meridian section of a sphere, or of a cylinder in plane
// strain) above a block, all quadrilaterals: x >= 0 is the radial coordinate,
// y the axis, the block's top is y = 0 and the disc's apex sits at y = gap.
// Physical groups follow meshes/README.md. Override the constants with
// gmsh -setnumber (or the reader's number overrides), e.g. n = 16.

DefineConstant[
  R = {1.0, Name "Parameters/Disc radius"},
  gap = {0.05, Name "Parameters/Gap at the apex"},
  W = {3.0, Name "Parameters/Block width"},
  H = {3.0, Name "Parameters/Block depth"},
  n = {6, Name "Parameters/Cells along each half of the arc"},
  m = {6, Name "Parameters/Cells across the surface layer of the disc"},
  nb = {12, Name "Parameters/Block cells per side"}
];

yc = gap + R;   // disc centre on the axis
a = 0.5 * R;    // half-size of the core square of the O-grid
s = 0.4 * R;    // its inner corner

// Disc: a core square and two curved patches (an O-grid).
Point(1) = {0, yc, 0};                          // centre
Point(2) = {0, yc - a, 0};                      // core corner on the axis
Point(3) = {0, gap, 0};                         // apex
Point(4) = {R * Sqrt(0.5), yc - R * Sqrt(0.5), 0};  // arc midpoint
Point(5) = {R, yc, 0};                          // equator end
Point(6) = {a, yc, 0};                          // core corner on the equator
Point(7) = {s, yc - s, 0};                      // core inner corner

Line(1) = {1, 2};        // axis, core
Line(2) = {2, 3};        // axis, surface layer
Line(3) = {1, 6};        // equator, core
Line(4) = {6, 5};        // equator, surface layer
Circle(5) = {3, 1, 4};   // arc, apex side
Circle(6) = {4, 1, 5};   // arc, equator side
Line(7) = {2, 7};
Line(8) = {6, 7};
Line(9) = {7, 4};

Curve Loop(1) = {1, 7, -8, -3};  Plane Surface(1) = {1};   // core
Curve Loop(2) = {2, 5, -9, -7};  Plane Surface(2) = {2};   // apex patch
Curve Loop(3) = {9, 6, -4, 8};   Plane Surface(3) = {3};   // equator patch

Transfinite Curve{1, 3, 5, 6, 7, 8} = n + 1;
Transfinite Curve{2, 4, 9} = m + 1 Using Progression 0.85;  // finer towards the arc

// Block [0, W] x [-H, 0], graded towards the contact at the origin.
Point(11) = {0, -H, 0};
Point(12) = {W, -H, 0};
Point(13) = {W, 0, 0};
Point(14) = {0, 0, 0};
Line(11) = {11, 12};   // bottom
Line(12) = {12, 13};   // far side
Line(13) = {14, 13};   // top, from the axis outward
Line(14) = {11, 14};   // axis, upward
Curve Loop(11) = {11, 12, -13, -14};  Plane Surface(11) = {11};
Transfinite Curve{11, 13} = nb + 1 Using Progression 1.15;
Transfinite Curve{12, 14} = nb + 1 Using Progression 0.87;

Transfinite Surface{1, 2, 3, 11};
Recombine Surface{1, 2, 3, 11};

Physical Surface("body:sphere") = {1, 2, 3};
Physical Surface("body:substrate") = {11};
Physical Curve("axis") = {1, 2, 14};
Physical Curve("driven") = {3, 4};
Physical Curve("fixed") = {11};
Physical Curve("contact:sphere") = {5, 6};
Physical Curve("contact:substrate") = {13};
Physical Point("apex") = {3};
Physical Point("lower apex") = {14};
