// The die of the drawbead strip: its face z = 0 with a groove across the strip at x = 0. The
// groove's shoulders (radius Rs) have their centres at x = +-a, a = Rb + Rs + t + c (bead radius
// Rb, sheet thickness t, clearance c), z = -Rs; vertical walls below them and a floor at z = -14.
// Profile in the x-z plane, extruded across the strip (y from -4 to 6).
Rs = 4; Rb = 4; t = 1; c = 0.5;
a = Rb + Rs + t + c;
n = 24;  // points on each shoulder's quarter circle (0.26 mm apart)
Point(1) = {-70, -4, 0};
Point(2) = {-a, -4, 0};
Point(3) = {-a, -4, -Rs};       // centre
Point(4) = {-a + Rs, -4, -Rs};
Point(5) = {-a + Rs, -4, -14};
Point(6) = {a - Rs, -4, -14};
Point(7) = {a - Rs, -4, -Rs};
Point(8) = {a, -4, -Rs};        // centre
Point(9) = {a, -4, 0};
Point(10) = {70, -4, 0};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Line(3) = {4, 5};
Line(4) = {5, 6};
Line(5) = {6, 7};
Circle(6) = {7, 8, 9};
Line(7) = {9, 10};
Transfinite Curve{2, 6} = n;
Transfinite Curve{1, 7} = 16;
Transfinite Curve{3, 5} = 6;
Transfinite Curve{4} = 6;
out[] = Extrude {0, 10, 0} { Curve{1, 2, 3, 4, 5, 6, 7}; Layers{5}; };
Physical Surface("die") = {out[1], out[5], out[9], out[13], out[17], out[21], out[25]};
