// gX[0 .. gCells]: positions on [0, gLength], first cell gFirst, then growing geometrically.
rFirst = gFirst; rCells = gCells; rShift = 0; rLength = gLength; Include "ratio.geo";
gX[0] = 0; gH = gFirst;
For gK In {1:gCells}
  gX[gK] = gX[gK - 1] + gH; gH *= rQ;
EndFor
gX[gCells] = gLength;
