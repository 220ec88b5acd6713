// rQ: the smallest q >= 1 with total(q) >= rLength, by the generator's bisection (solveRatio).
rR = 1; Include "total.geo";
rQ = 1;
If (rS < rLength)
  rLo = 1; rHi = 2; rDone = 0;
  For rIt In {1:64}
    If (rDone == 0)
      rR = rHi; Include "total.geo";
      If (rS < rLength)
        rHi *= 2;
      Else
        rDone = 1;
      EndIf
    EndIf
  EndFor
  For rIt In {1:200}
    rMid = 0.5 * (rLo + rHi);
    rR = rMid; Include "total.geo";
    If (rS < rLength)
      rLo = rMid;
    Else
      rHi = rMid;
    EndIf
  EndFor
  rQ = 0.5 * (rLo + rHi);
EndIf
