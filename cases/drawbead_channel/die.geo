// NUMISHEET'93 2-D draw bending (U-channel): quarter of the rigid die (x >= 0, y >= 0; the die is
// a straight prism along y, its profile in the x-z plane). Units: mm.
// Only the contact side is kept: the die's top face at z = -0.37 (= -t/2, touching the bottom
// surface of the 0.74 mm strip whose mid-surface is at z = 0) from the profile radius out to
// x = 180, the 5 mm profile radius rounding it into the cavity, and the cavity's vertical wall
// x = 35.814 down to z = -80 (the punch bottom reaches z = -69.63 at the 70 mm stroke; the
// cavity has no floor in this benchmark). Faces in y = 0, y = 20, x = 180 and z = -80 are
// removed.
// Source: NUMISHEET'93 benchmark specification as listed in ../../docs/references.md: die
// profile radius 5 mm, punch width 70 mm (grade C); t = 0.74 mm (grade C).
// ASSUMPTION (grade C, not from the specification): the cavity's half width 35.814 mm = the punch
// half width 35 mm + a clearance of t + 10 % = 0.814 mm per side (cavity 71.628 mm wide); the
// benchmark's cavity width was not found in the public material searched (README.md).
// The 180 mm outer extent (the strip ends at 175 and only draws in), the 20 mm extent across
// the width (strip: 17.5) and the 80 mm depth are our choices.
// Mesh normals point out of the tool, towards the blank (gmsh 4.8 meshes OCC solid faces with
// outward normals; tests/meshing/test_gmsh_reader.cpp checks it).
// Mesh: 3-node triangles. Element size: Mesh.MeshSizeMax when the caller sets it (sheetform's
// element_size, or `gmsh -2 -clmax 1 die.geo`), else 2 mm; refined on the profile radius by
// Mesh.MeshSizeFromCurvature (elements per 2 pi of curvature: 64, i.e. 16 per quarter arc).
SetFactory("OpenCASCADE");

punch_half_width = 35;  // mm
clearance = 0.814;      // mm per side: t + 10 % (assumption, see above)
half_opening = punch_half_width + clearance;  // mm
profile_radius = 5;     // mm
outer = 180;            // mm, extent in x
extent_y = 20;          // mm, across the width (strip: 17.5)
z_top = -0.74 / 2;      // mm
z_bottom = -80;         // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 64;

// Quarter die: the block beside the cavity, then the profile fillet on its top edge along y at
// the cavity wall.
Box(1) = {half_opening, 0, z_bottom, outer - half_opening, extent_y, z_top - z_bottom};
eps = 1e-6;
edge() = Curve In BoundingBox{half_opening - eps, -eps, z_top - eps,
                              half_opening + eps, extent_y + eps, z_top + eps};
die() = Fillet{1}{edge()}{profile_radius};

// Keep only the contact side: drop the faces in y = 0, y = extent_y, x = outer and z = z_bottom.
faces() = Boundary{ Volume{die(0)}; };
drop() = Surface In BoundingBox{half_opening - eps, -eps, z_bottom - eps, outer + eps, eps, z_top + eps};
drop() += Surface In BoundingBox{half_opening - eps, extent_y - eps, z_bottom - eps, outer + eps, extent_y + eps, z_top + eps};
drop() += Surface In BoundingBox{outer - eps, -eps, z_bottom - eps, outer + eps, extent_y + eps, z_top + eps};
drop() += Surface In BoundingBox{half_opening - eps, -eps, z_bottom - eps, outer + eps, extent_y + eps, z_bottom + eps};
keep() = faces();
keep() -= drop();
Delete{ Volume{die(0)}; }
Recursive Delete{ Surface{drop()}; }  // with their curves and points not used by kept faces
Physical Surface("die") = keep();
