// rl[]: the curves cl[] in reverse order and direction (negated ids).
rl[] = {};
For pK In {0:#cl[] - 1}
  rl[pK] = -cl[#cl[] - 1 - pK];
EndFor
