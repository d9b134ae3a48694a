// NUMISHEET'93 2-D draw bending (U-channel): quarter of the rigid punch (x >= 0, y >= 0; the
// punch is a straight prism along y, its profile in the x-z plane). Units: mm.
// Only the contact side is kept: the flat bottom face at z = +0.37 (= t/2, touching the top
// surface of the 0.74 mm strip whose mid-surface is at z = 0), the 5 mm profile radius and the
// vertical side wall x = 35 up to z = 90 (the strip's wall reaches about z = 70 above the punch
// bottom at the 70 mm stroke). Faces in the symmetry planes x = 0 and y = 0, the outer face
// y = 20 and the top face are removed. The punch moves in -z.
// Source: NUMISHEET'93 benchmark specification as listed in ../../docs/references.md: punch
// width 70 mm, profile radius 5 mm (grade C); t = 0.74 mm (grade C). The 20 mm extent across
// the width (the strip's half width is 17.5 mm) and the 90 mm height are our choices.
// Mesh normals point out of the tool, towards the blank (gmsh 4.8 meshes OCC solid faces with
// outward normals; tests/meshing/test_gmsh_reader.cpp checks it).
// Mesh: 3-node triangles. Element size: Mesh.MeshSizeMax when the caller sets it (sheetform's
// element_size, or `gmsh -2 -clmax 1 punch.geo`), else 2 mm; refined on the profile radius by
// Mesh.MeshSizeFromCurvature (elements per 2 pi of curvature: 64, i.e. 16 per quarter arc,
// chord sag 5 (1 - cos(pi / 32)) = 0.024 mm).
SetFactory("OpenCASCADE");

half_width = 35;        // mm
profile_radius = 5;     // mm
extent_y = 20;          // mm, across the width (strip: 17.5)
z_bottom = 0.74 / 2;    // mm
z_top = 90;             // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 64;

// Quarter punch: a box, then the profile fillet on its bottom edge along y at x = half_width.
Box(1) = {0, 0, z_bottom, half_width, extent_y, z_top - z_bottom};
eps = 1e-6;
edge() = Curve In BoundingBox{half_width - eps, -eps, z_bottom - eps,
                              half_width + eps, extent_y + eps, z_bottom + eps};
punch() = Fillet{1}{edge()}{profile_radius};

// Keep only the contact side: drop the faces in x = 0, y = 0, y = extent_y and z = z_top.
faces() = Boundary{ Volume{punch(0)}; };
drop() = Surface In BoundingBox{-eps, -eps, z_bottom - eps, eps, extent_y + eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_bottom - eps, half_width + eps, eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, extent_y - eps, z_bottom - eps, half_width + eps, extent_y + eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_top - eps, half_width + eps, extent_y + eps, z_top + eps};
keep() = faces();
keep() -= drop();
Delete{ Volume{punch(0)}; }
Recursive Delete{ Surface{drop()}; }  // with their curves and points not used by kept faces
Physical Surface("punch") = keep();
