// NUMISHEET'93 square cup: quarter of the rigid die (x >= 0, y >= 0; cup axis = z axis).
// Units: mm. Only the contact side is kept: the die's top face at z = -0.405 (= -t/2, touching the
// bottom surface of the 0.81 mm blank whose mid-surface is at z = 0) out to x, y = 90, the 8 mm
// profile radius rounding it into the opening, and the vertical opening wall down to z = -60.
// Faces in the symmetry planes, the outer faces and the bottom face are removed.
// Source: NUMISHEET'93 benchmark specification, values as listed in ../../docs/references.md:
// die opening 74 x 74 mm, plan corner radius 12 mm, profile radius 8 mm (grade C);
// t = 0.81 mm (grade A). The 90 mm outer extent is our choice (beyond the 75 mm blank).
// Mesh normals point out of the tool, towards the blank (gmsh 4.8 meshes OCC solid faces with
// outward normals; tests/meshing/test_gmsh_reader.cpp checks it).
// Mesh: 3-node triangles. Element size: Mesh.MeshSizeMax when the caller sets it (sheetform's
// element_size, or `gmsh -2 -clmax 1 die.geo`), else 2 mm; refined on the profile radius by
// Mesh.MeshSizeFromCurvature (elements per 2 pi of curvature: 32, i.e. 8 per quarter arc).
SetFactory("OpenCASCADE");

half_opening = 37;      // mm
corner_radius = 12;     // mm, in plan
DefineConstant[ profile_radius = {8, Name "Parameters/die profile radius (mm)"} ];  // mm
outer = 90;             // mm, quarter extent in x and y
z_top = -0.81 / 2;      // mm
z_bottom = -60;         // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;

// Full die: a plate with a rounded-square opening, then the profile fillet on the opening edge.
Box(1) = {-outer, -outer, z_bottom, 2 * outer, 2 * outer, z_top - z_bottom};
Box(2) = {-half_opening, -half_opening, z_bottom - 1, 2 * half_opening, 2 * half_opening,
          z_top - z_bottom + 2};
eps = 1e-6;
vertical_edges() = Curve In BoundingBox{-half_opening - eps, -half_opening - eps, z_bottom - 1 - eps,
                                        half_opening + eps, half_opening + eps, z_top + 1 + eps};
vertical_edges() -= Curve In BoundingBox{-outer, -outer, z_bottom - 1 - eps, outer, outer,
                                         z_bottom - 1 + eps};
vertical_edges() -= Curve In BoundingBox{-outer, -outer, z_top + 1 - eps, outer, outer,
                                         z_top + 1 + eps};
opening() = Fillet{2}{vertical_edges()}{corner_radius};
plate() = BooleanDifference{ Volume{1}; Delete; }{ Volume{opening(0)}; Delete; };
opening_edge() = Curve In BoundingBox{-half_opening - eps, -half_opening - eps, z_top - eps,
                                      half_opening + eps, half_opening + eps, z_top + eps};
die() = Fillet{plate(0)}{opening_edge()}{profile_radius};

// Quarter: x >= 0, y >= 0.
Box(100) = {0, 0, z_bottom - 1, outer + 1, outer + 1, z_top - z_bottom + 2};
quarter() = BooleanIntersection{ Volume{die(0)}; Delete; }{ Volume{100}; Delete; };

// Keep only the contact side: drop the faces in x = 0, y = 0, x = outer, y = outer, z = z_bottom.
faces() = Boundary{ Volume{quarter(0)}; };
drop() = Surface In BoundingBox{-eps, -eps, z_bottom - eps, eps, outer + eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_bottom - eps, outer + eps, eps, z_top + eps};
drop() += Surface In BoundingBox{outer - eps, -eps, z_bottom - eps, outer + eps, outer + eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, outer - eps, z_bottom - eps, outer + eps, outer + eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_bottom - eps, outer + eps, outer + eps, z_bottom + eps};
keep() = faces();
keep() -= drop();
Delete{ Volume{quarter(0)}; }
Recursive Delete{ Surface{drop()}; }  // with their curves and points not used by kept faces
Physical Surface("die") = keep();
