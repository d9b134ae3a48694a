// The strip: 60 x 5 mm in the z = 0 plane, 80 x 2 quadrilaterals (0.75 x 2.5 mm).
// Groups: blank (surface), back (edge x = 0), sides (edges y = 0 and y = 5).
Point(1) = {0, 0, 0}; Point(2) = {60, 0, 0}; Point(3) = {60, 5, 0}; Point(4) = {0, 5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 81;
Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("back") = {4};
Physical Curve("sides") = {1, 3};
Physical Curve("tip") = {2};
