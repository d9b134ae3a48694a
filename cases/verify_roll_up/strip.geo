// Cantilever strip of the roll-up verification: 100 x 10 mm in the z = 0 plane, clamped at x = 0,
// an end moment at x = 100. Units: mm. Structured: 20 x 1 quadrilaterals (the case file keeps the
// file's own sizes). Groups: blank (surface), clamp (edge x = 0), tip (edge x = 100).
L = 100;  // mm, length
b = 10;   // mm, width
DefineConstant[ n = 20 ];  // elements along the length (a case sets it: blank.parameters.n)
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
Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("clamp") = {4};
Physical Curve("tip") = {2};
