// Trim lines for tests/meshing/test_curve_loop.cpp (units: mm). "trim": the rectangle
// [0, 50] x [0, 30] with its corner at (50, 30) rounded by a quarter circle of radius 10, enclosing
// 50 * 30 - (10^2 - pi 10^2 / 4) = 1478.54 mm^2; one of its lines drawn against the others. "open":
// two of its sides; "branch": the loop and a line from a corner; "two": the loop and a square
// apart.
Point(1) = {0, 0, 0};
Point(2) = {50, 0, 0};
Point(3) = {50, 20, 0};
Point(4) = {40, 30, 0};
Point(5) = {0, 30, 0};
Point(6) = {40, 20, 0};  // the arc's centre
Line(1) = {1, 2};
Line(2) = {2, 3};
Circle(3) = {3, 6, 4};
Line(4) = {4, 5};
Line(5) = {1, 5};  // against the others
Point(7) = {-10, -10, 0};
Line(6) = {1, 7};
Point(8) = {100, 0, 0};
Point(9) = {110, 0, 0};
Point(10) = {110, 10, 0};
Point(11) = {100, 10, 0};
Line(7) = {8, 9};
Line(8) = {9, 10};
Line(9) = {10, 11};
Line(10) = {11, 8};
Physical Curve("trim") = {1, 2, 3, 4, 5};
Physical Curve("open") = {1, 2};
Physical Curve("branch") = {1, 2, 3, 4, 5, 6};
Physical Curve("two") = {1, 2, 3, 4, 5, 7, 8, 9, 10};
