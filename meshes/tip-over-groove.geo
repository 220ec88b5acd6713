// A cylindrical tip over the groove between two cylindrical ridges, plane
// strain, drawn for x >= 0: the quarter of the tip (radius R, centre on x = 0)
// below its equator, and the substrate [0, W] x [-H, 0] with one ridge (a
// disc of radius r, centre (d, hr), fused with it). The deck mirrors it in
// x = 0 (Geometry/Mirror Planes = {x}): the whole model, node for node
// symmetric, whose tip is attracted by two flanks at once. The tip's flank
// and the ridge are `gap` apart along the line of their centres, at `alpha`
// degrees from the vertical; the tip's apex is above the groove's floor. The
// tip's equator is "driven" (Driven Components = all: a clamp that moves
// down), the substrate's bottom "fixed"; no "apex" (u = 0 is the drawn
// position, the flanks `gap` apart). Cells of lc within zone of the closest
// points, growing to lcFar. Physical groups follow meshes/README.md.

SetFactory("OpenCASCADE");

DefineConstant[
  R = {1.0, Name "Parameters/Tip radius"},
  r = {0.5, Name "Parameters/Ridge radius"},
  alpha = {60, Name "Parameters/Angle of the line of centres from the vertical (degrees)"},
  gap = {0.05, Name "Parameters/Gap between tip and ridge"},
  rise = {0.2, Name "Parameters/Height of the tip's apex above the groove's floor"},
  W = {3.0, Name "Parameters/Substrate half width"},
  H = {1.5, Name "Parameters/Substrate depth"},
  lc = {0.02, Name "Parameters/Cell size at the closest points"},
  lcFar = {0.2, Name "Parameters/Cell size far from them"},
  zone = {0.15, Name "Parameters/Extent of the finest cells"}
];

a = alpha * Pi / 180;
L = R + r + gap;            // distance of the centres
zc = R + rise;              // the tip's centre
d = L * Sin(a);             // the ridge's centre
hr = zc - L * Cos(a);
If (d - r <= 0 || hr + r <= 0 || d + r >= W)
  Error("tip-over-groove: the ridge must lie inside 0 < x < W and rise above the floor");
  Abort;
EndIf

// the tip: the quarter x >= 0 of the disc below its equator
Disk(1) = {0, zc, 0, R};
Rectangle(2) = {0, zc - R, 0, R, R};
tip[] = BooleanIntersection{ Surface{1}; Delete; }{ Surface{2}; Delete; };
// the substrate: the block and the ridge, fused, cut at x = 0
Rectangle(3) = {0, -H, 0, W, H};
Disk(4) = {d, hr, 0, r};
rough[] = BooleanUnion{ Surface{3}; Delete; }{ Surface{4}; Delete; };
Rectangle(5) = {0, -H, 0, W, H + hr + r + 1};
substrate[] = BooleanIntersection{ Surface{rough[]}; Delete; }{ Surface{5}; Delete; };

e = 1e-6 * R;
tipTop[] = Curve In BoundingBox{-e, zc - e, -e, R + e, zc + e, e};
tipMirror[] = Curve In BoundingBox{-e, zc - R - e, -e, e, zc + e, e};
tipAll[] = Boundary{ Surface{tip[]}; };
bottom[] = Curve In BoundingBox{-e, -H - e, -e, W + e, -H + e, e};
subMirror[] = Curve In BoundingBox{-e, -H - e, -e, e, hr + r + e, e};
subRight[] = Curve In BoundingBox{W - e, -H - e, -e, W + e, hr + r + e, e};
subAll[] = Boundary{ Surface{substrate[]}; };
tipArc[] = {};
For i In {0 : #tipAll[] - 1}
  c = Abs(tipAll[i]);
  If (c != tipTop[0] && c != tipMirror[0])
    tipArc[] += c;
  EndIf
EndFor
subTop[] = {};
For i In {0 : #subAll[] - 1}
  c = Abs(subAll[i]);
  If (c != bottom[0] && c != subMirror[0] && c != subRight[0])
    subTop[] += c;
  EndIf
EndFor

// the closest points: on the line of centres
mx = (L - r - 0.5 * gap) * Sin(a);
my = zc - (R + 0.5 * gap) * Cos(a);
Field[1] = MathEval;
Field[1].F = Sprintf("Sqrt((x - %g)^2 + (y - %g)^2)", mx, my);
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lc;
Field[2].SizeMax = lcFar;
Field[2].DistMin = zone;
Field[2].DistMax = 4 * zone + 10 * (lcFar - lc);
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
Recombine Surface{tip[], substrate[]};

Physical Surface("body:tip") = {tip[]};
Physical Surface("body:substrate") = {substrate[]};
Physical Curve("driven") = {tipTop[]};
Physical Curve("fixed") = {bottom[]};
Physical Curve("symmetry x") = {tipMirror[], subMirror[]};
Physical Curve("contact:tip") = {tipArc[]};
Physical Curve("contact:substrate") = {subTop[]};
