// Rigid tools of the three-point bending springback tests (with bend_strip.geo, t = 1 mm):
// "punch", a cylinder of radius 10 mm along y centred at (0, 10.5) in x-z, touching the strip's
// top surface at x = 0; "support", a cylinder of radius 5 mm centred at (45, -5.5), touching its
// bottom surface at x = 45. Only the arcs facing the strip are kept. Triangles, about 1 mm.
Mesh.MeshSizeMax = 1.0;
// punch: from 120 to 60 degrees below its centre's horizontal, through the lowest point
Point(1) = {0, -1, 10.5};
Point(2) = {-10 * Sin(Pi / 6), -1, 10.5 - 10 * Cos(Pi / 6)};
Point(3) = {0, -1, 0.5};
Point(4) = {10 * Sin(Pi / 3), -1, 10.5 - 10 * Cos(Pi / 3)};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
punch[] = Extrude {0, 7, 0} { Curve{1, 2}; Layers{7}; };
// support: the upper half of its circle
Point(11) = {45, -1, -5.5};
Point(12) = {40, -1, -5.5};
Point(13) = {45, -1, -0.5};
Point(14) = {50, -1, -5.5};
Circle(11) = {12, 11, 13};
Circle(12) = {13, 11, 14};
support[] = Extrude {0, 7, 0} { Curve{11, 12}; Layers{7}; };
Physical Surface("punch") = {punch[1], punch[5]};
Physical Surface("support") = {support[1], support[5]};
