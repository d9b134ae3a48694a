// Scordelis-Lo roof (MacNeal & Harder 1985): a cylindrical roof of radius 25, length 50, spanning
// 80 degrees (40 on each side of the crown), thickness 0.25. The quarter x >= 0, y >= 0: the
// axis is y, the crown the line x = 0 (z = 25), the free edge at 40 degrees, the diaphragm at
// y = 25 (the roof's end), the mid-span section y = 0. Structured n x n quadrilaterals. Units:
// the benchmark's consistent set (lengths in feet in the original). Groups: blank (surface),
// crown (x = 0: symmetry), mid_span (y = 0: symmetry), diaphragm (y = 25), probe (the free
// edge at mid-span, point A of the benchmark).
DefineConstant[ n = {16, Name "Parameters/elements per side"} ];
R = 25; L = 50; phi = 40 * Pi / 180;
Point(1) = {0, 0, 0};                             // centre of the arcs, mid-span
Point(2) = {0, 0, R};                             // crown, mid-span
Point(3) = {R * Sin(phi), 0, R * Cos(phi)};       // free edge, mid-span (A)
Point(4) = {0, L / 2, 0};                         // centre of the arcs, end
Point(5) = {0, L / 2, R};                         // crown, end
Point(6) = {R * Sin(phi), L / 2, R * Cos(phi)};   // free edge, end
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
Physical Curve("crown") = {4};
Physical Curve("mid_span") = {1};
Physical Curve("diaphragm") = {3};
Physical Point("probe") = {3};
