// Cylindrical cup: a quarter of the rigid blank holder (x >= 0, y >= 0; cup axis = z axis). Only
// the contact side: the flat annular face at z = +t/2 (touching the top surface of the blank of
// thickness t, the parameter `thickness`, 0.78 mm by default, whose mid-surface is at z = 0), from the die opening's radius plus 1 mm (38 mm)
// out to 80 mm. Units: mm. Dimensions: README.md (our choice, as for the square cup's holder).
// Mesh: 3-node triangles. Element size: Mesh.MeshSizeMax when the caller sets it, else 2 mm.
SetFactory("OpenCASCADE");

inner = 37 + 1;         // mm, die opening radius + 1 mm
outer = 80;             // mm
DefineConstant[ thickness = {0.78, Name "Parameters/blank thickness (mm)"} ];  // mm
z_face = thickness / 2;  // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;

Disk(1) = {0, 0, z_face, outer, outer};
Disk(2) = {0, 0, z_face, inner, inner};
ring() = BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; };
Rectangle(3) = {0, 0, z_face, outer + 1, outer + 1};
holder() = BooleanIntersection{ Surface{ring()}; Delete; }{ Surface{3}; Delete; };
// Orient the mesh so its normal is -z: out of the holder, towards the blank, like the punch and the
// die (whose OCC solid faces are meshed with outward normals).
ReverseMesh Surface{holder()};
Physical Surface("holder") = holder();
