// Test data: a 100 x 10 mm strip in the z = 0 plane, meshed half with quadrilaterals and half
// with triangles (read it with blank.element = "as_meshed", which keeps the file's own Recombine
// commands). x in [0, 50]: 10 x 2 transfinite quads; x in [50, 100]: 10 x 2 transfinite cells
// cut into 40 triangles. 63 nodes, 20 quads, 40 triangles. Groups: blank (both surfaces), clamp
// (edge x = 0), tip (edge x = 100).
L = 100; b = 10;
Point(1) = {0, 0, 0}; Point(2) = {L / 2, 0, 0}; Point(3) = {L, 0, 0};
Point(4) = {L, b, 0}; Point(5) = {L / 2, b, 0}; Point(6) = {0, b, 0};
Line(1) = {1, 2}; Line(2) = {2, 5}; Line(3) = {5, 6}; Line(4) = {6, 1};
Line(5) = {2, 3}; Line(6) = {3, 4}; Line(7) = {4, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Transfinite Curve{1, 3, 5, 7} = 11;
Transfinite Curve{2, 4, 6} = 3;
Transfinite Surface{1};
Transfinite Surface{2};
Recombine Surface{1};
Physical Surface("blank") = {1, 2};
Physical Curve("clamp") = {4};
Physical Curve("tip") = {6};
