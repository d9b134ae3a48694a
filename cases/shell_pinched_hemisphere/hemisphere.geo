// Pinched hemisphere with an 18-degree hole (MacNeal & Harder 1985): radius 10, thickness 0.04,
// four alternating radial loads on the equator. The quarter x >= 0, y >= 0: latitude 0 (the
// equator, z = 0) to 72 degrees (the hole's edge), longitude 0 to 90. Structured n x n
// quadrilaterals on the sphere. Units: the benchmark's consistent set. Groups: blank (surface),
// xz_plane (y = 0), yz_plane (x = 0), load_x (on the equator at (10, 0, 0), pushed outwards),
// load_y (at (0, 10, 0), pulled inwards).
DefineConstant[ n = {16, Name "Parameters/elements per side"} ];
R = 10; top = 72 * Pi / 180;
Point(1) = {0, 0, 0};                                   // centre
Point(2) = {R, 0, 0};                                   // equator, longitude 0
Point(3) = {0, R, 0};                                   // equator, longitude 90
Point(4) = {R * Cos(top), 0, R * Sin(top)};             // hole edge, longitude 0
Point(5) = {0, R * Cos(top), R * Sin(top)};             // hole edge, longitude 90
Point(6) = {0, 0, R * Sin(top)};                        // centre of the hole's circle
Circle(1) = {2, 1, 3};                                  // equator
Circle(2) = {3, 1, 5};                                  // meridian x = 0
Circle(3) = {5, 6, 4};                                  // hole edge
Circle(4) = {4, 1, 2};                                  // meridian y = 0
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1} In Sphere {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("xz_plane") = {4};
Physical Curve("yz_plane") = {2};
Physical Point("load_x") = {2};
Physical Point("load_y") = {3};
