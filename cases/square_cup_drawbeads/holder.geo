// NUMISHEET'93 square cup: quarter of the rigid blank holder (x >= 0, y >= 0; cup axis = z axis).
// Units: mm. Only the contact side: the flat annular face at z = +0.405 (= t/2, touching the top
// surface of the 0.81 mm blank whose mid-surface is at z = 0), from the die opening outline offset
// by 1 mm (quarter 38 x 38 with plan corner radius 13) out to x, y = 90.
// Source: NUMISHEET'93 benchmark specification, values as listed in ../../docs/references.md:
// die opening 74 x 74 mm, plan corner radius 12 mm (grade C); t = 0.81 mm (grade A). The 1 mm
// offset and the 90 mm outer extent are our choices.
// Mesh: 3-node triangles. Element size: Mesh.MeshSizeMax when the caller sets it (sheetform's
// element_size, or `gmsh -2 -clmax 1 holder.geo`), else 2 mm.
SetFactory("OpenCASCADE");

half_opening = 37 + 1;  // mm, die opening + 1 mm offset
corner_radius = 12 + 1; // mm, in plan
outer = 90;             // mm, quarter extent in x and y
z_face = 0.81 / 2;      // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;

Rectangle(1) = {0, 0, z_face, outer, outer};
Rectangle(2) = {-half_opening, -half_opening, z_face, 2 * half_opening, 2 * half_opening,
                corner_radius};
holder() = BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; };
// Orient the mesh so its normal is -z: out of the holder, towards the blank, like the punch and the
// die (whose OCC solid faces are meshed with outward normals).
ReverseMesh Surface{holder()};
Physical Surface("holder") = holder();
