// Rectangular cup (cases/rectangular_cup_cad): the quarter blank (x >= 0, y >= 0; symmetry planes
// x = 0 and y = 0). Units: mm. A 130 x 100 x 0.81 mm blank (our choice, the aluminium sheet of
// ../square_cup_aluminium); mid-surface at z = 0; the thickness is set in the case file.
// Mesh: structured quadrilaterals (transfinite + Recombine). Element size: Mesh.MeshSizeMax when
// the caller sets it (sheetform's element_size), else 2 mm.
SetFactory("OpenCASCADE");

half_x = 65;  // mm, half of the 130 mm blank length
half_y = 50;  // mm, half of the 100 mm blank width
h = 2;        // mm, default element size
If (Mesh.MeshSizeMax < 1e21)
  h = Mesh.MeshSizeMax;
EndIf
nx = Ceil(half_x / h - 1e-9);  // elements along x (at least the size asked for)
ny = Ceil(half_y / h - 1e-9);  // elements along y

Rectangle(1) = {0, 0, 0, half_x, half_y};
eps = 1e-6;
Transfinite Curve{Curve In BoundingBox{-eps, -eps, -eps, half_x + eps, eps, eps}} = nx + 1;
Transfinite Curve{Curve In BoundingBox{-eps, half_y - eps, -eps, half_x + eps, half_y + eps, eps}} = nx + 1;
Transfinite Curve{Curve In BoundingBox{-eps, -eps, -eps, eps, half_y + eps, eps}} = ny + 1;
Transfinite Curve{Curve In BoundingBox{half_x - eps, -eps, -eps, half_x + eps, half_y + eps, eps}} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};

Physical Surface("blank") = {1};
Physical Curve("sym_x") = Curve In BoundingBox{-eps, -eps, -eps, eps, half_y + eps, eps};
Physical Curve("sym_y") = Curve In BoundingBox{-eps, -eps, -eps, half_x + eps, eps, eps};
// Draw-in measurement points: the mid-points of the full blank's edges on the x and y axes, and
// its corner.
Physical Point("edge_mid_x") = Point In BoundingBox{half_x - eps, -eps, -eps, half_x + eps, eps, eps};
Physical Point("edge_mid_y") = Point In BoundingBox{-eps, half_y - eps, -eps, eps, half_y + eps, eps};
Physical Point("corner") = Point In BoundingBox{half_x - eps, half_y - eps, -eps, half_x + eps, half_y + eps, eps};
