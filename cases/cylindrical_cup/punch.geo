// Cylindrical cup: a quarter of the rigid flat-bottomed punch (x >= 0, y >= 0; cup axis = z axis),
// diameter 70 mm, profile radius 8 mm (the NUMISHEET'93 square cup's punch section turned round:
// README.md). Its flat face at z = +t/2 touches the top surface of the blank of thickness t (the
// parameter `thickness`, 0.78 mm by default; mid-surface at z = 0). Only the contact side is kept: the flat bottom, the profile and the side wall, with
// normals outwards (towards the blank). Units: mm.
// Mesh: 3-node triangles. Element size: Mesh.MeshSizeMax when the caller sets it (sheetform's
// element_size, or `gmsh -2 -clmax 1 punch.geo`), else 2 mm.
SetFactory("OpenCASCADE");

radius = 35;            // mm
profile_radius = 8;     // mm
DefineConstant[ thickness = {0.78, Name "Parameters/blank thickness (mm)"} ];  // mm
z_bottom = thickness / 2;  // mm
z_top = 60;             // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;

Cylinder(1) = {0, 0, z_bottom, 0, 0, z_top - z_bottom, radius};
eps = 1e-6;
bottom_edge() = Curve In BoundingBox{-radius - eps, -radius - eps, z_bottom - eps,
                                     radius + eps, radius + eps, z_bottom + eps};
punch() = Fillet{1}{bottom_edge()}{profile_radius};

Box(100) = {0, 0, z_bottom - 1, radius + 1, radius + 1, z_top - z_bottom + 2};
quarter() = BooleanIntersection{ Volume{punch(0)}; Delete; }{ Volume{100}; Delete; };

faces() = Boundary{ Volume{quarter(0)}; };
drop() = Surface In BoundingBox{-eps, -eps, z_bottom - eps, eps, radius + eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_bottom - eps, radius + eps, eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_top - eps, radius + eps, radius + eps, z_top + eps};
keep() = faces();
keep() -= drop();
Delete{ Volume{quarter(0)}; }
Recursive Delete{ Surface{drop()}; }  // with their curves and points not used by kept faces
Physical Surface("punch") = keep();
