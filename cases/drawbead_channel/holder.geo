// NUMISHEET'93 2-D draw bending (U-channel): quarter of the rigid blank holder (x >= 0, y >= 0).
// Units: mm. Only the contact side: the flat face at z = +0.37 (= t/2, touching the top surface
// of the 0.74 mm strip whose mid-surface is at z = 0), from the die cavity's edge offset by
// 1 mm (x = 36.814) out to x = 180, across the width to y = 20.
// Source: NUMISHEET'93 benchmark specification as listed in ../../docs/references.md
// (t = 0.74 mm, grade C). The cavity half width 35.814 mm is an assumption (die.geo); the 1 mm
// offset, the 180 mm outer extent and the 20 mm extent across the width are our choices.
// Mesh: 3-node triangles. Element size: Mesh.MeshSizeMax when the caller sets it (sheetform's
// element_size, or `gmsh -2 -clmax 1 holder.geo`), else 2 mm.
SetFactory("OpenCASCADE");

inner = 35 + 0.814 + 1;  // mm, die cavity half width + 1 mm offset
outer = 180;             // mm, extent in x
extent_y = 20;           // mm, across the width (strip: 17.5)
z_face = 0.74 / 2;       // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf

Rectangle(1) = {inner, 0, z_face, outer - inner, extent_y};
// Orient the mesh so its normal is -z: out of the holder, towards the blank, like the punch and the
// die (whose OCC solid faces are meshed with outward normals).
ReverseMesh Surface{1};
Physical Surface("holder") = {1};
