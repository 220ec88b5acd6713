// Bad input: two bodies drawn into each other (the upper square's corner lies in the lower one).
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(11) = {0, 0.8, 0}; Point(12) = {0.7, 0.8, 0}; Point(13) = {0.7, 1.5, 0}; Point(14) = {0, 1.5, 0};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14}; Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
Transfinite Curve{1, 2, 3, 4, 11, 12, 13, 14} = 3;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface("body:lower") = {1};
Physical Surface("body:upper") = {2};
Physical Curve("fixed") = {1};
Physical Curve("driven") = {13};
Physical Curve("axis") = {4, 14};
