// The bouncing plate: one 10 x 10 mm quadrilateral shell, mid-surface at z = 0. Units: mm.
// Groups: blank (the surface).
Point(1) = {0, 0, 0};
Point(2) = {10, 0, 0};
Point(3) = {10, 10, 0};
Point(4) = {0, 10, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{:} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
