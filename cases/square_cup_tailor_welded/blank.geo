// Tailor-welded blank for the NUMISHEET'93 square cup: half of the 150 x 150 mm blank (y >= 0;
// symmetry plane y = 0), welded along x = 0 from a 1.2 mm sheet (x <= 0, "thick") and a 0.8 mm
// sheet (x >= 0, "thin"). Units: mm. Mid-surface at z = 0; the thicknesses are set in the case
// file, not here. The two surfaces share the weld curve, so its nodes are both parts' nodes.
// Mesh: structured quadrilaterals (transfinite + Recombine). Element size: Mesh.MeshSizeMax when
// the caller sets it (sheetform's element_size), else 2.5 mm.
half_width = 75;  // mm, half of the 150 mm blank
h = 2.5;          // mm, default element size
If (Mesh.MeshSizeMax < 1e21)
  h = Mesh.MeshSizeMax;
EndIf
n = Ceil(half_width / h - 1e-9);  // elements per edge (at least the size asked for)

Point(1) = {-half_width, 0, 0};
Point(2) = {0, 0, 0};
Point(3) = {half_width, 0, 0};
Point(4) = {half_width, half_width, 0};
Point(5) = {0, half_width, 0};
Point(6) = {-half_width, half_width, 0};
Line(1) = {1, 2};  // y = 0, thick side
Line(2) = {2, 3};  // y = 0, thin side
Line(3) = {3, 4};  // x = +75
Line(4) = {4, 5};  // y = 75, thin side
Line(5) = {5, 6};  // y = 75, thick side
Line(6) = {6, 1};  // x = -75
Line(7) = {2, 5};  // the weld, x = 0
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Transfinite Curve{1:7} = n + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("blank") = {1, 2};
Physical Surface("thick") = {1};
Physical Surface("thin") = {2};
Physical Curve("sym_y") = {1, 2};
Physical Curve("weld") = {7};
// Probes: the weld at the cup's centre line and at the blank's edge, and the edge mid-points of
// the two sides (on the symmetry plane).
Physical Point("weld_centre") = {2};
Physical Point("weld_edge") = {5};
Physical Point("edge_mid_thick") = {1};
Physical Point("edge_mid_thin") = {3};
