// NUMISHEET'93 2-D draw bending (U-channel): quarter of the strip (x >= 0, y >= 0; symmetry
// planes x = 0, the channel's middle, and y = 0, the strip's middle line along its length).
// Units: mm. Mid-surface at z = 0; thickness 0.74 mm is set in the case file, not here.
// Source: NUMISHEET'93 benchmark specification as listed in ../../docs/references.md
// (strip 350 x 35 mm, t = 0.74 mm: grade C).
// Mesh: structured quadrilaterals (transfinite + Recombine). Along x: Mesh.MeshSizeMax when the
// caller sets it (sheetform's element_size, or `gmsh -2 -clmax 1 blank.geo`), else 1.25 mm,
// i.e. about 6 elements over the 7.85 mm arc of a 5 mm tool radius. Across the width: 4
// elements (4.375 mm) whatever the size: the strip bends in plane strain, nothing varies much
// across it but the anticlastic curl at its free edge.
SetFactory("OpenCASCADE");

half_length = 175;   // mm, half of the 350 mm strip
half_width = 17.5;   // mm, half of the 35 mm strip
h = 1.25;            // mm, default element size along x
If (Mesh.MeshSizeMax < 1e21)
  h = Mesh.MeshSizeMax;
EndIf
nx = Ceil(half_length / h - 1e-9);  // elements along x (at least the size asked for)
ny = 4;                             // elements across the half width

Rectangle(1) = {0, 0, 0, half_length, half_width};
eps = 1e-6;
along_x() = Curve In BoundingBox{-eps, -eps, -eps, half_length + eps, eps, eps};
along_x() += Curve In BoundingBox{-eps, half_width - eps, -eps, half_length + eps, half_width + eps, eps};
across() = Curve In BoundingBox{-eps, -eps, -eps, eps, half_width + eps, eps};
across() += Curve In BoundingBox{half_length - eps, -eps, -eps, half_length + eps, half_width + eps, eps};
Transfinite Curve{along_x()} = nx + 1;
Transfinite Curve{across()} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};

Physical Surface("blank") = {1};
Physical Curve("sym_x") = Curve In BoundingBox{-eps, -eps, -eps, eps, half_width + eps, eps};
Physical Curve("sym_y") = Curve In BoundingBox{-eps, -eps, -eps, half_length + eps, eps, eps};
// The line of nodes on y = 0 (the same as sym_y) on which the springback measures theta1, theta2
// and rho are taken ([springback.u_channel] section).
Physical Curve("section") = Curve In BoundingBox{-eps, -eps, -eps, half_length + eps, eps, eps};
// Draw-in: the strip's end on its middle line.
Physical Point("end") = Point In BoundingBox{half_length - eps, -eps, -eps, half_length + eps, eps, eps};
