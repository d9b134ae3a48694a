// Verification, membrane patch test: a 10 x 10 mm square in the z = 0 plane cut into four
// quadrilaterals around an interior node moved off the centre, to (4.2, 6.1), so that no element
// is a parallelogram. Edge nodes are evenly spaced (5 mm), so consistent nodal loads are a
// quarter (corners) and a half (mid-edge node) of an edge's resultant. Units: mm. Groups: blank;
// left (x = 0), bottom (y = 0); right_corners (10, 0) and (10, 10); right_mid (10, 5);
// top_corners (0, 10) and (10, 10). (The same mesh as tests/data/patch_distorted.geo.)
Point(1) = {0, 0, 0};  Point(2) = {5, 0, 0};  Point(3) = {10, 0, 0};
Point(4) = {0, 5, 0};  Point(5) = {4.2, 6.1, 0};  Point(6) = {10, 5, 0};
Point(7) = {0, 10, 0}; Point(8) = {5, 10, 0}; Point(9) = {10, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 5}; Line(4) = {5, 6};
Line(5) = {7, 8}; Line(6) = {8, 9}; Line(7) = {1, 4}; Line(8) = {4, 7};
Line(9) = {2, 5}; Line(10) = {5, 8}; Line(11) = {3, 6}; Line(12) = {6, 9};
Curve Loop(1) = {1, 9, -3, -7};   Plane Surface(1) = {1};
Curve Loop(2) = {2, 11, -4, -9};  Plane Surface(2) = {2};
Curve Loop(3) = {3, 10, -5, -8};  Plane Surface(3) = {3};
Curve Loop(4) = {4, 12, -6, -10}; Plane Surface(4) = {4};
Transfinite Curve{1:12} = 2;
Transfinite Surface{1:4};
Recombine Surface{1:4};
Physical Surface("blank") = {1:4};
Physical Curve("left") = {7, 8};
Physical Curve("bottom") = {1, 2};
Physical Point("right_corners") = {3, 9};
Physical Point("right_mid") = {6};
Physical Point("top_corners") = {7, 9};
