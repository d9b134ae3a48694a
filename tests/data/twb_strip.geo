// Tailor-welded strip: 100 x 10 mm in the z = 0 plane, 20 x 1 quadrilaterals of 5 mm, welded at
// x = 40. Surface 1 ("outer") is x in [40, 100], surface 2 ("inner") x in [0, 40]: they share
// the weld curve, so its nodes are the two parts' common nodes. Groups: blank (both surfaces),
// inner, outer, clamp (edge x = 0), weld (x = 40), tip (edge x = 100).
L = 100; b = 10; w = 40;
Point(1) = {w, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, b, 0}; Point(4) = {w, b, 0};
Point(5) = {0, 0, 0}; Point(6) = {0, b, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 1}; Line(6) = {4, 6}; Line(7) = {6, 5};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, -4, 6, 7};
Plane Surface(2) = {2};
Transfinite Curve{1, 3} = 13;
Transfinite Curve{5, 6} = 9;
Transfinite Curve{2, 4, 7} = 2;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface("blank") = {1, 2};
Physical Surface("outer") = {1};
Physical Surface("inner") = {2};
Physical Curve("clamp") = {7};
Physical Curve("weld") = {4};
Physical Curve("tip") = {2};
