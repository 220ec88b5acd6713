// total(q) = sum over k < rCells of rFirst q^(k + rShift), accumulated in the
// generator's order; input rR (= q), output rS.
rS = 0; rT = rFirst;
For rK In {0:rCells - 1}
  If (rShift)
    rT *= rR; rS += rT;
  Else
    rS += rT; rT *= rR;
  EndIf
EndFor
