// Cantilever under end shear (Sze, Liu & Lo 2004): length 10, width 1, clamped at x = 0, a
// transverse tip load. Structured nl x 1 quadrilaterals (16 x 1 by default, the paper's mesh).
// Units: the benchmark's consistent set. Groups: blank (surface), clamp (x = 0), tip (x = 10).
DefineConstant[ nl = {16, Name "Parameters/elements along"} ];
L = 10; b = 1;
Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, b, 0};
Point(4) = {0, b, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nl + 1;
Transfinite Curve{2, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("clamp") = {4};
Physical Curve("tip") = {2};
