// Three-point bending strip for the springback tests: half of a 120 x 10 mm strip (symmetry planes
// x = 0 and y = 0), 60 x 5 mm in the z = 0 plane, 40 x 3 quadrilaterals. Groups: blank, sym_x
// (edge x = 0), sym_y (edge y = 0).
L = 60; b = 5;
Point(1) = {0, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, b, 0}; Point(4) = {0, b, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 41;
Transfinite Curve{2, 4} = 4;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("sym_x") = {4};
Physical Curve("sym_y") = {1};
