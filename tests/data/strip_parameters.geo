// Test data: the cantilever strip of strip.geo with its element count n and width b as parameters
// (DefineConstant: a case's blank.parameters sets them): 100 x b mm in the z = 0 plane, n x 1
// quadrilaterals. Groups: blank (surface), clamp (edge x = 0), tip (edge x = 100), tip_corner
// (the point (100, 0, 0)).
DefineConstant[ n = 20, b = 10 ];
L = 100;
Point(1) = {0, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, b, 0}; Point(4) = {0, b, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("clamp") = {4};
Physical Curve("tip") = {2};
Physical Point("tip_corner") = {2};
