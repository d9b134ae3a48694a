// NUMISHEET'93 square cup: half of the rigid die (y >= 0; cup axis = z axis), for the
// tailor-welded blank: stepped at the weld. Units: mm. Only the contact side: the top face at
// z = -0.6 under the thick sheet (x <= 1.25) and at z = -0.4 under the thin one (x >= 1.25),
// half each sheet's thickness below the aligned mid-surfaces, so that both rest on it; out to
// x = +-90 and y = 90, the 8 mm profile radius into the opening and the opening wall down to
// z = -60. Each side is the full die at its height cut at x = 1.25, the two joined by a 0.2 mm
// step face half an element beyond the weld: the weld's nodes (at the mean of the two
// thicknesses, 0.5 mm) stand 0.1 mm clear of the thick side's face, and the step's averaged
// normals stay away from the nodes on either side (at 0.25 mm the weld nodes started 0.03 mm
// inside it). The faces in the symmetry plane, the outer faces and the bottom face are removed.
// Source: NUMISHEET'93 benchmark specification, values as listed in ../../docs/references.md:
// die opening 74 x 74 mm, plan corner radius 12 mm, profile radius 8 mm (grade C). The 90 mm
// outer extent and the step are our choices.
// Mesh normals point out of the tool (OCC solid faces are meshed with outward normals).
// Mesh: 3-node triangles, Mesh.MeshSizeMax when the caller sets it, else 2 mm; refined on the
// profile radius (32 elements per 2 pi of curvature).
SetFactory("OpenCASCADE");

half_opening = 37;      // mm
corner_radius = 12;     // mm, in plan
profile_radius = 8;     // mm
outer = 90;             // mm
z_bottom = -60;         // mm
split = 1.25;           // mm, the step's x
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;
eps = 1e-6;

// side = 0: the thick side (x <= split, top -0.6); side = 1: the thin side (x >= split, -0.4).
For side In {0 : 1}
  z_top = side == 0 ? -1.2 / 2 : -0.8 / 2;
  b = 10 * side;  // tag offset
  Box(1 + b) = {-outer, -outer, z_bottom, 2 * outer, 2 * outer, z_top - z_bottom};
  Box(2 + b) = {-half_opening, -half_opening, z_bottom - 1, 2 * half_opening, 2 * half_opening,
                z_top - z_bottom + 2};
  vertical_edges() = Curve In BoundingBox{-half_opening - eps, -half_opening - eps,
                                          z_bottom - 1 - eps, half_opening + eps,
                                          half_opening + eps, z_top + 1 + eps};
  vertical_edges() -= Curve In BoundingBox{-outer, -outer, z_bottom - 1 - eps, outer, outer,
                                           z_bottom - 1 + eps};
  vertical_edges() -= Curve In BoundingBox{-outer, -outer, z_top + 1 - eps, outer, outer,
                                           z_top + 1 + eps};
  opening() = Fillet{2 + b}{vertical_edges()}{corner_radius};
  plate() = BooleanDifference{ Volume{1 + b}; Delete; }{ Volume{opening(0)}; Delete; };
  opening_edge() = Curve In BoundingBox{-half_opening - eps, -half_opening - eps, z_top - eps,
                                        half_opening + eps, half_opening + eps, z_top + eps};
  full() = Fillet{plate(0)}{opening_edge()}{profile_radius};
  x0 = side == 0 ? -outer - 1 : split;
  x1 = side == 0 ? split : outer + 1;
  Box(100 + b) = {x0, 0, z_bottom - 1, x1 - x0, outer + 1, z_top - z_bottom + 2};
  part~{side}() = BooleanIntersection{ Volume{full(0)}; Delete; }{ Volume{100 + b}; Delete; };
EndFor

die() = BooleanUnion{ Volume{part~{0}(0)}; Delete; }{ Volume{part~{1}(0)}; Delete; };

// Keep only the contact side: drop the faces in y = 0, x = +-outer, y = outer and the bottom.
faces() = Boundary{ Volume{die(0)}; };
drop() = Surface In BoundingBox{-outer - eps, -eps, z_bottom - eps, outer + eps, eps, 1};
drop() += Surface In BoundingBox{outer - eps, -eps, z_bottom - eps, outer + eps, outer + eps, 1};
drop() += Surface In BoundingBox{-outer - eps, -eps, z_bottom - eps, -outer + eps, outer + eps, 1};
drop() += Surface In BoundingBox{-outer - eps, outer - eps, z_bottom - eps, outer + eps, outer + eps, 1};
drop() += Surface In BoundingBox{-outer - eps, -eps, z_bottom - eps, outer + eps, outer + eps,
                                 z_bottom + eps};
keep() = faces();
keep() -= drop();
Delete{ Volume{die(0)}; }
Recursive Delete{ Surface{drop()}; }
Physical Surface("die") = keep();
