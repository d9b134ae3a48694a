// Cylindrical cup: a quarter of the circular blank (x >= 0, y >= 0; symmetry planes x = 0 and
// y = 0), radius 70 mm (diameter 140 mm: drawing ratio 2.0 on the 70 mm punch), mid-surface at
// z = 0. Units: mm. Source of the dimensions: README.md (our choice).
// Mesh: a structured "O-grid" of quadrilaterals (an inner quadrilateral and two outer blocks up
// to the rim; transfinite + Recombine), with rim nodes at 0, 45 and 90 degrees for the draw-ins.
// Element size: the case file's element_size (Mesh.MeshSizeMax), else 2.5 mm; the rim's elements
// come out about 1.3 x it, the centre's 0.8 x. (gmsh 4.8's Frontal-Delaunay for quads crashes on
// a quarter disc: hence the blocks.)
R = 70;          // mm, blank radius
h = 2.5;         // mm, default element size
If (Mesh.MeshSizeMax < 1e21)
  h = Mesh.MeshSizeMax;
EndIf
a = 0.5 * R;     // the inner block's corners on the axes
c = 0.42 * R;    // and on the diagonal
n_around = Ceil(0.5 * (Pi / 4 * R + a) / h);  // elements along an arc half / an inner edge
n_radial = Ceil((R - a) / h);                  // elements from the inner block to the rim

Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {c, c, 0};
Point(4) = {0, a, 0};
Point(5) = {R, 0, 0};
Point(6) = {R * Sqrt(0.5), R * Sqrt(0.5), 0};
Point(7) = {0, R, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {2, 5};
Circle(6) = {5, 1, 6};
Line(7) = {6, 3};
Circle(8) = {6, 1, 7};
Line(9) = {7, 4};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {-7, 8, 9, -3};
Plane Surface(3) = {3};
Transfinite Curve{1, 2, 3, 4, 6, 8} = n_around + 1;
Transfinite Curve{5, 7, 9} = n_radial + 1;
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};

Physical Surface("blank") = {1, 2, 3};
Physical Curve("sym_y") = {1, 5};   // on y = 0
Physical Curve("sym_x") = {4, 9};   // on x = 0
Physical Point("rim_0") = {5};      // the rim at 0 degrees (rolling direction, x)
Physical Point("rim_45") = {6};     // at 45 degrees
Physical Point("rim_90") = {7};     // at 90 degrees (transverse, y)
