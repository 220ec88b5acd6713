// Part of the benchmark meshes (packages/mesh/src/Benchmark.cpp), node for
// node. Every boundary node is a point and every cell edge on a patch
// boundary a curve with 2 nodes, so the transfinite patches reproduce the
// generator: its interior nodes lie on straight rays (quarter disc) or on a
// tensor grid (block), which is what transfinite interpolation gives between
// boundaries discretised that way. The files of meshes/include take and set
// global variables. Keep every Include last on its line: gmsh 4.8 runs what
// follows it on the same line first.
//
// Quarter disc of radius qR centred at (0, qCy) on the axis, apex pointing
// down (qSy = -1) or up (qSy = 1), fine cells over the polar angle qFine from
// the apex, refinement level qLevel. Sets qSurfaces[], qAxis[] (curves on
// x = 0), qEquator[] (the flat side), qArc[] (the curved side) and the point qApex.
qM = 2^qLevel; qCoreFrac = 0.5; qC = qCoreFrac * qR;
fLength = Pi / 4; fFine = qFine; fFineCells = 16 * qM; fCoarseCells = 8 * qM; Include "fine-then-geometric.geo";
qNB = 24 * qM; qNC = 8 * qM; qNR = 14 * qM;
For qI In {0:qNB}
  qThB[qI] = fX[qI];
EndFor
For qJ In {0:qNC}
  qThC[qJ] = Pi / 4 + (Pi / 4) * qJ / qNC;
EndFor
gLength = 1; gFirst = qFine / (16 * qM) / (1 - qCoreFrac); gCells = qNR; Include "geometric.geo";
For qK In {0:qNR}
  qT[qK] = 1 - gX[qNR - qK];
EndFor

// Core [0, c] x [0, c] in (x, y'), y' from the centre towards the apex; y = qCy + qSy y'.
For qI In {0:qNB}   // apex-side edge y' = c
  qCoreApex[qI] = newp; Point(qCoreApex[qI]) = {qC * Tan(qThB[qI]), qCy + qSy * qC / Tan(qThC[0]), 0};
EndFor
qCoreOut[0] = qCoreApex[qNB];
For qJ In {1:qNC}   // outer edge x = c
  qCoreOut[qJ] = newp; Point(qCoreOut[qJ]) = {qC * Tan(qThB[qNB]), qCy + qSy * qC / Tan(qThC[qJ]), 0};
EndFor
qCoreAxis[0] = qCoreApex[0];
For qJ In {1:qNC}   // axis edge x = 0
  qCoreAxis[qJ] = newp; Point(qCoreAxis[qJ]) = {0, qCy + qSy * qC / Tan(qThC[qJ]), 0};
EndFor
qCoreEq[0] = qCoreAxis[qNC];
For qI In {1:qNB - 1}   // equator edge y' = 0
  qCoreEq[qI] = newp; Point(qCoreEq[qI]) = {qC * Tan(qThB[qI]), qCy + qSy * qC / Tan(qThC[qNC]), 0};
EndFor
qCoreEq[qNB] = qCoreOut[qNC];

// Rays from the core to the arc: the axis (theta = 0), the diagonal (pi/4), the equator (pi/2).
qCentre = newp; Point(qCentre) = {0, qCy, 0};
For qK In {1:qNR}
  qX0 = qC * Tan(qThB[0]); qX1 = qR * Sin(qThB[0]); qY1 = qR * Cos(qThB[0]);
  qRayAxis[qK] = newp; Point(qRayAxis[qK]) = {qX0 + qT[qK] * (qX1 - qX0), qCy + qSy * (qC + qT[qK] * (qY1 - qC)), 0};
  qX0 = qC * Tan(qThB[qNB]); qX1 = qR * Sin(qThB[qNB]); qY1 = qR * Cos(qThB[qNB]);
  qRayDiag[qK] = newp; Point(qRayDiag[qK]) = {qX0 + qT[qK] * (qX1 - qX0), qCy + qSy * (qC + qT[qK] * (qY1 - qC)), 0};
  qY0 = qC / Tan(qThC[qNC]); qX1 = qR * Sin(qThC[qNC]); qY1 = qR * Cos(qThC[qNC]);
  qRayEq[qK] = newp; Point(qRayEq[qK]) = {qC + qT[qK] * (qX1 - qC), qCy + qSy * (qY0 + qT[qK] * (qY1 - qY0)), 0};
EndFor
qRayAxis[0] = qCoreApex[0]; qRayDiag[0] = qCoreApex[qNB]; qRayEq[0] = qCoreOut[qNC];
// Arc points by polar angle from the apex; the rays end on it.
qArcPt[0] = qRayAxis[qNR];
For qI In {1:qNB - 1}
  qArcPt[qI] = newp; Point(qArcPt[qI]) = {qR * Sin(qThB[qI]), qCy + qSy * qR * Cos(qThB[qI]), 0};
EndFor
qArcPt[qNB] = qRayDiag[qNR];
For qJ In {1:qNC - 1}
  qArcPt[qNB + qJ] = newp; Point(qArcPt[qNB + qJ]) = {qR * Sin(qThC[qJ]), qCy + qSy * qR * Cos(qThC[qJ]), 0};
EndFor
qArcPt[qNB + qNC] = qRayEq[qNR];

pl[] = qCoreApex[]; Include "polyline.geo";
qLApex[] = cl[];
pl[] = qCoreOut[]; Include "polyline.geo";
qLOut[] = cl[];
pl[] = qCoreAxis[]; Include "polyline.geo";
qLAxis[] = cl[];
pl[] = qCoreEq[]; Include "polyline.geo";
qLEq[] = cl[];
pl[] = qRayAxis[]; Include "polyline.geo";
qLRayAxis[] = cl[];
pl[] = qRayDiag[]; Include "polyline.geo";
qLRayDiag[] = cl[];
pl[] = qRayEq[]; Include "polyline.geo";
qLRayEq[] = cl[];
qArc[] = {};
For qI In {0:qNB + qNC - 1}
  qArc[qI] = newl; Circle(qArc[qI]) = {qArcPt[qI], qCentre, qArcPt[qI + 1]};
EndFor
qArcB[] = qArc[{0:qNB - 1}];
qArcC[] = qArc[{qNB:qNB + qNC - 1}];

// Curve loops: every side in order, reversed sides negated.
cl[] = qLEq[]; Include "reversed.geo";
qREq[] = rl[];
cl[] = qLAxis[]; Include "reversed.geo";
qRAxis[] = rl[];
cl[] = qArcB[]; Include "reversed.geo";
qRArcB[] = rl[];
cl[] = qArcC[]; Include "reversed.geo";
qRArcC[] = rl[];
cl[] = qLRayAxis[]; Include "reversed.geo";
qRRayAxis[] = rl[];
cl[] = qLRayDiag[]; Include "reversed.geo";
qRRayDiag[] = rl[];
qLoop = newll; Curve Loop(qLoop) = {qLApex[], qLOut[], qREq[], qRAxis[]};
qCore = news; Plane Surface(qCore) = {qLoop};
Transfinite Surface{qCore} = {qCoreApex[0], qCoreApex[qNB], qCoreOut[qNC], qCoreAxis[qNC]};
qLoop = newll; Curve Loop(qLoop) = {qLApex[], qLRayDiag[], qRArcB[], qRRayAxis[]};
qPatchB = news; Plane Surface(qPatchB) = {qLoop};
Transfinite Surface{qPatchB} = {qCoreApex[0], qCoreApex[qNB], qArcPt[qNB], qArcPt[0]};
qLoop = newll; Curve Loop(qLoop) = {qLOut[], qLRayEq[], qRArcC[], qRRayDiag[]};
qPatchC = news; Plane Surface(qPatchC) = {qLoop};
Transfinite Surface{qPatchC} = {qCoreOut[0], qCoreOut[qNC], qArcPt[qNB + qNC], qArcPt[qNB]};

qSurfaces[] = {qCore, qPatchB, qPatchC};
Transfinite Curve{qLApex[], qLOut[], qLAxis[], qLEq[], qLRayAxis[], qLRayDiag[], qLRayEq[], qArc[]} = 2;
Recombine Surface{qSurfaces[]};
qAxis[] = {qLAxis[], qLRayAxis[]};
qEquator[] = {qLEq[], qLRayEq[]};
qApex = qArcPt[0];
