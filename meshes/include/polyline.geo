// A polyline of straight lines through the points pl[]: curve ids in cl[].
cl[] = {};
For pK In {0:#pl[] - 2}
  cl[pK] = newl; Line(cl[pK]) = {pl[pK], pl[pK + 1]};
EndFor
