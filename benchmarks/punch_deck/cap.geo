// The punch deck's tool (issue 16): a rigid spherical cap, sphere R 50 mm, base radius 30 mm
// (height 10 mm), apex 1 mm above the plate's mid-surface at the plate's centre (50, 50).
R = 50; a = 30; h = R - Sqrt(R^2 - a^2);
zA = 1.0;                     // apex
Point(1) = {50, 50, zA + R};  // sphere centre
Point(2) = {50, 50, zA};      // apex
Point(3) = {50, 50, zA + h};  // base circle centre
Point(4) = {50 + a, 50, zA + h}; Point(5) = {50, 50 + a, zA + h};
Point(6) = {50 - a, 50, zA + h}; Point(7) = {50, 50 - a, zA + h};
Circle(1) = {4, 3, 5}; Circle(2) = {5, 3, 6}; Circle(3) = {6, 3, 7}; Circle(4) = {7, 3, 4};
Circle(5) = {2, 1, 4}; Circle(6) = {2, 1, 5}; Circle(7) = {2, 1, 6}; Circle(8) = {2, 1, 7};
Curve Loop(1) = {5, 1, -6}; Surface(1) = {1};
Curve Loop(2) = {6, 2, -7}; Surface(2) = {2};
Curve Loop(3) = {7, 3, -8}; Surface(3) = {3};
Curve Loop(4) = {8, 4, -5}; Surface(4) = {4};
Physical Surface("cap") = {1, 2, 3, 4};
