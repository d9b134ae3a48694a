// NUMISHEET'93 square cup, tailor-welded blank: the blank holder over the thick side (x <= 0,
// y >= 0; a split, stepped holder: each sheet has its own, at its own height). Units: mm. Only the
// contact side: the flat face at z = +0.6 (half the thick sheet's thickness), from the die opening
// outline offset by 1 mm (plan corner radius 13) out to 90 mm, and from 0.5 mm off the weld (the
// weld's nodes, at the mean of the two thicknesses, stand clear of both holders).
// Source: NUMISHEET'93 benchmark specification, values as listed in ../../docs/references.md:
// die opening 74 x 74 mm, plan corner radius 12 mm (grade C). The 1 mm offset, the 90 mm outer
// extent and the split at the weld are our choices.
// Mesh: 3-node triangles, Mesh.MeshSizeMax when the caller sets it, else 2 mm.
SetFactory("OpenCASCADE");

half_opening = 37 + 1;  // mm, die opening + 1 mm offset
corner_radius = 12 + 1; // mm, in plan
outer = 90;             // mm
z_face = 1.2 / 2;       // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;

Rectangle(1) = {-outer, 0, z_face, outer - 0.5, outer};
Rectangle(2) = {-half_opening, -half_opening, z_face, 2 * half_opening, 2 * half_opening,
                corner_radius};
holder() = BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; };
// Normal -z: out of the holder, towards the blank, as the punch's and the die's.
ReverseMesh Surface{holder()};
Physical Surface("holder_thick") = holder();
