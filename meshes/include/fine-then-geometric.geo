// fX[0 .. fFineCells + fCoarseCells]: fFineCells equal cells up to fFine, then
// fCoarseCells growing geometrically to fLength.
fH = fFine / fFineCells;
For fK In {0:fFineCells}
  fX[fK] = fH * fK;
EndFor
rFirst = fH; rCells = fCoarseCells; rShift = 1; rLength = fLength - fFine; Include "ratio.geo";
fT = fH;
For fK In {1:fCoarseCells}
  fT *= rQ; fX[fFineCells + fK] = fX[fFineCells + fK - 1] + fT;
EndFor
fX[fFineCells + fCoarseCells] = fLength;
