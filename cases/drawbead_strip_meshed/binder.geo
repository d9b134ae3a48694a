// The binder of the drawbead strip, meshed where it stands closed on the sheet: its face z = t
// with a round bead across the strip at x = 0, radius Rb, its crest `depth` below the face
// (centre at z = t - depth + Rb); with depth = Rb the bead is a half cylinder. The case lowers it
// by `lift` to that place. Profile in the x-z plane, extruded across the strip.
Rb = 4; t = 1; depth = 4; lift = 4;
z0 = t + lift;  // the face where the binder is meshed
n = 24;
Point(1) = {-70, -4, z0};
Point(2) = {-Rb, -4, z0};
Point(3) = {0, -4, z0 - depth + Rb};  // centre
Point(4) = {0, -4, z0 - depth};
Point(5) = {Rb, -4, z0};
Point(6) = {70, -4, z0};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Circle(3) = {4, 3, 5};
Line(4) = {5, 6};
Transfinite Curve{2, 3} = n;
Transfinite Curve{1, 4} = 16;
out[] = Extrude {0, 10, 0} { Curve{1, 2, 3, 4}; Layers{5}; };
Physical Surface("binder") = {out[1], out[5], out[9], out[13]};
