// NUMISHEET'93 square cup: quarter of the blank (x >= 0, y >= 0; symmetry planes x = 0 and y = 0).
// Units: mm. Mid-surface at z = 0; thickness 0.81 mm is set in the case file, not here.
// Source: NUMISHEET'93 benchmark specification, values as listed in ../../docs/references.md
// (blank 150 x 150 mm, t = 0.81 mm: grade A).
// Mesh: structured quadrilaterals (transfinite + Recombine). Element size: Mesh.MeshSizeMax when
// the caller sets it (sheetform's element_size, or `gmsh -2 -clmax 1.25 blank.geo`), else 2.5 mm.
SetFactory("OpenCASCADE");

half_width = 75;  // mm, half of the 150 mm blank
h = 2.5;          // mm, default element size
If (Mesh.MeshSizeMax < 1e21)
  h = Mesh.MeshSizeMax;
EndIf
n = Ceil(half_width / h - 1e-9);  // elements per edge (at least the size asked for)

Rectangle(1) = {0, 0, 0, half_width, half_width};
Transfinite Curve{:} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};

eps = 1e-6;
Physical Surface("blank") = {1};
Physical Curve("sym_x") = Curve In BoundingBox{-eps, -eps, -eps, eps, half_width + eps, eps};
Physical Curve("sym_y") = Curve In BoundingBox{-eps, -eps, -eps, half_width + eps, eps, eps};
// Draw-in measurement points: edge mid-points of the full blank on the x and y axes, and its corner.
Physical Point("edge_mid_x") = Point In BoundingBox{half_width - eps, -eps, -eps, half_width + eps, eps, eps};
Physical Point("edge_mid_y") = Point In BoundingBox{-eps, half_width - eps, -eps, eps, half_width + eps, eps};
Physical Point("corner") = Point In BoundingBox{half_width - eps, half_width - eps, -eps, half_width + eps, half_width + eps, eps};
