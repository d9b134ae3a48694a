// Pinched cylinder with end diaphragms (MacNeal & Harder 1985; Belytschko et al. 1985): radius
// 300, length 600, thickness 3, two opposite radial loads at mid-length. The eighth x >= 0,
// y >= 0, z >= 0: the axis is y, the load point on top (0, 0, 300) at mid-length y = 0, the
// diaphragm at y = 300. Structured n x n quadrilaterals. Units: the benchmark's consistent set.
// Groups: blank (surface), top (x = 0), side (z = 0), mid_length (y = 0), diaphragm (y = 300),
// load (the load point).
DefineConstant[ n = {16, Name "Parameters/elements per side"} ];
R = 300; L = 600;
Point(1) = {0, 0, 0};           // centre, mid-length
Point(2) = {0, 0, R};           // top, mid-length: the load point
Point(3) = {R, 0, 0};           // side, mid-length
Point(4) = {0, L / 2, 0};       // centre, end
Point(5) = {0, L / 2, R};       // top, end
Point(6) = {R, L / 2, 0};       // side, end
Circle(1) = {2, 1, 3};
Line(2) = {3, 6};
Circle(3) = {6, 4, 5};
Line(4) = {5, 2};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("top") = {4};
Physical Curve("side") = {2};
Physical Curve("mid_length") = {1};
Physical Curve("diaphragm") = {3};
Physical Point("load") = {2};
