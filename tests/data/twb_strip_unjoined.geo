// The strip of twb_strip.geo meshed as two surfaces that do not share the weld curve: each has
Geometry.AutoCoherence = 0;  // keep the duplicate points at x = 40
// its own nodes at x = 40 (a weld line meshed twice, so the parts are not joined).
L = 100; b = 10; w = 40;
Point(1) = {w, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, b, 0}; Point(4) = {w, b, 0};
Point(5) = {0, 0, 0}; Point(6) = {0, b, 0}; Point(7) = {w, 0, 0}; Point(8) = {w, b, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 7}; Line(6) = {7, 8}; Line(7) = {8, 6}; Line(8) = {6, 5};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{1, 3} = 13;
Transfinite Curve{5, 7} = 9;
Transfinite Curve{2, 4, 6, 8} = 2;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface("blank") = {1, 2};
Physical Surface("outer") = {1};
Physical Surface("inner") = {2};
Physical Curve("clamp") = {8};
Physical Curve("tip") = {2};
