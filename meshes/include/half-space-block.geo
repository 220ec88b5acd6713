// Part of the benchmark meshes, node for node (see quarter-disc.geo).
//
// Block [0, bW] x [bTop - bH, bTop], graded towards (0, bTop): bFine of the
// top edge in 20 equal cells (per level), then geometric; the depth starts
// with that cell size and grows geometrically. Sets bSurface, bAxis[],
// bBottom[], bTopEdge[], bSide[] and the point bApex at (0, bTop).
bM = 2^bLevel;
fLength = bW; fFine = bFine; fFineCells = 20 * bM; fCoarseCells = 10 * bM; Include "fine-then-geometric.geo";
bNX = 30 * bM;
For bI In {0:bNX}
  bXs[bI] = fX[bI];
EndFor
gLength = bH; gFirst = bFine / (20 * bM); gCells = 20 * bM; Include "geometric.geo";
bNY = gCells;
For bI In {0:bNX}
  bTopPt[bI] = newp; Point(bTopPt[bI]) = {bXs[bI], bTop, 0};
  bBotPt[bI] = newp; Point(bBotPt[bI]) = {bXs[bI], bTop - bH, 0};
EndFor
bAxisPt[0] = bTopPt[0]; bSidePt[0] = bTopPt[bNX];
For bK In {1:bNY - 1}
  bAxisPt[bK] = newp; Point(bAxisPt[bK]) = {0, bTop - gX[bK], 0};
  bSidePt[bK] = newp; Point(bSidePt[bK]) = {bW, bTop - gX[bK], 0};
EndFor
bAxisPt[bNY] = bBotPt[0]; bSidePt[bNY] = bBotPt[bNX];
pl[] = bTopPt[]; Include "polyline.geo";
bTopEdge[] = cl[];
pl[] = bBotPt[]; Include "polyline.geo";
bBottom[] = cl[];
pl[] = bAxisPt[]; Include "polyline.geo";
bAxis[] = cl[];
pl[] = bSidePt[]; Include "polyline.geo";
bSide[] = cl[];
cl[] = bSide[]; Include "reversed.geo";
bRSide[] = rl[];
cl[] = bTopEdge[]; Include "reversed.geo";
bRTop[] = rl[];
bLoop = newll; Curve Loop(bLoop) = {bBottom[], bRSide[], bRTop[], bAxis[]};
bSurface = news; Plane Surface(bSurface) = {bLoop};
Transfinite Curve{bTopEdge[], bBottom[], bAxis[], bSide[]} = 2;
Transfinite Surface{bSurface} = {bBotPt[0], bBotPt[bNX], bTopPt[bNX], bTopPt[0]};
Recombine Surface{bSurface};
bApex = bTopPt[0];
