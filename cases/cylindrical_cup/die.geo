// Cylindrical cup: a quarter of the rigid die (x >= 0, y >= 0; cup axis = z axis), opening
// diameter 74 mm, profile radius 8 mm (the NUMISHEET'93 square cup's die section turned round:
// README.md). Its top face at z = -t/2 touches the bottom surface of the blank of thickness t
// (the parameter `thickness`: 0.78 mm, or a case's tools[].parameters; mid-surface at z = 0). Only the contact side is kept: the top face out to a radius of 80 mm,
// the profile and the opening's wall, with normals outwards (towards the blank). Units: mm.
// Mesh: 3-node triangles. Element size: Mesh.MeshSizeMax when the caller sets it, else 2 mm.
SetFactory("OpenCASCADE");

opening_radius = 37;    // mm
profile_radius = 8;     // mm
outer = 80;             // mm, radius of the die's top face
DefineConstant[ thickness = {0.78, Name "Parameters/blank thickness (mm)"} ];  // mm
z_top = -thickness / 2;  // mm
z_bottom = -60;         // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;

Cylinder(1) = {0, 0, z_bottom, 0, 0, z_top - z_bottom, outer};
Cylinder(2) = {0, 0, z_bottom - 1, 0, 0, z_top - z_bottom + 2, opening_radius};
plate() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
eps = 1e-6;
opening_edge() = Curve In BoundingBox{-opening_radius - eps, -opening_radius - eps, z_top - eps,
                                      opening_radius + eps, opening_radius + eps, z_top + eps};
die() = Fillet{plate(0)}{opening_edge()}{profile_radius};

Box(100) = {0, 0, z_bottom - 1, outer + 1, outer + 1, z_top - z_bottom + 2};
quarter() = BooleanIntersection{ Volume{die(0)}; Delete; }{ Volume{100}; Delete; };

faces() = Boundary{ Volume{quarter(0)}; };
// Keep the top face, the profile and the opening's wall; drop the faces on the symmetry planes,
// the bottom and the outer cylinder (the only face reaching both the outer radius and below the top).
keep() = {};
drop() = {};
For i In {0 : #faces() - 1}
  bb() = BoundingBox Surface{faces(i)};  // xmin, ymin, zmin, xmax, ymax, zmax
  If (bb(3) < eps || bb(4) < eps || bb(5) < z_bottom + eps || (bb(3) > outer - 1 && bb(2) < z_top - 1))
    drop() += faces(i);
  Else
    keep() += faces(i);
  EndIf
EndFor
Delete{ Volume{quarter(0)}; }
Recursive Delete{ Surface{drop()}; }  // with their curves and points not used by kept faces
Physical Surface("die") = keep();
