// NUMISHEET'93 square cup: quarter of the rigid punch (x >= 0, y >= 0; cup axis = z axis).
// Units: mm. Only the contact side is kept: the flat bottom face at z = +0.405 (= t/2, touching
// the top surface of the 0.81 mm blank whose mid-surface is at z = 0), the 8 mm profile radius
// and the side walls up to z = 60. Faces in the symmetry planes and the top face are removed.
// The punch moves in -z.
// Source: NUMISHEET'93 benchmark specification, values as listed in ../../docs/references.md:
// punch 70 x 70 mm, plan corner radius 10 mm, profile radius 8 mm (grade C); t = 0.81 mm (grade A).
// Mesh normals point out of the tool, towards the blank (gmsh 4.8 meshes OCC solid faces with
// outward normals; tests/meshing/test_gmsh_reader.cpp checks it).
// Mesh: 3-node triangles. Element size: Mesh.MeshSizeMax when the caller sets it (sheetform's
// element_size, or `gmsh -2 -clmax 1 punch.geo`), else 2 mm; refined on the profile radius by
// Mesh.MeshSizeFromCurvature (elements per 2 pi of curvature: 32, i.e. 8 per quarter arc).
SetFactory("OpenCASCADE");

half_width = 35;        // mm
corner_radius = 10;     // mm, in plan
profile_radius = 8;     // mm
z_bottom = 0.81 / 2;    // mm
z_top = 60;             // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;

// Full punch: rounded square prism, then the profile fillet on the bottom edge loop.
Box(1) = {-half_width, -half_width, z_bottom, 2 * half_width, 2 * half_width, z_top - z_bottom};
eps = 1e-6;
vertical_edges() = Curve In BoundingBox{-half_width - eps, -half_width - eps, z_bottom - eps,
                                        half_width + eps, half_width + eps, z_top + eps};
bottom_edges() = Curve In BoundingBox{-half_width - eps, -half_width - eps, z_bottom - eps,
                                      half_width + eps, half_width + eps, z_bottom + eps};
vertical_edges() -= bottom_edges();
top_edges() = Curve In BoundingBox{-half_width - eps, -half_width - eps, z_top - eps,
                                   half_width + eps, half_width + eps, z_top + eps};
vertical_edges() -= top_edges();
rounded() = Fillet{1}{vertical_edges()}{corner_radius};
bottom_loop() = Curve In BoundingBox{-half_width - eps, -half_width - eps, z_bottom - eps,
                                     half_width + eps, half_width + eps, z_bottom + eps};
punch() = Fillet{rounded(0)}{bottom_loop()}{profile_radius};

// Quarter: x >= 0, y >= 0.
Box(100) = {0, 0, z_bottom - 1, half_width + 1, half_width + 1, z_top - z_bottom + 2};
quarter() = BooleanIntersection{ Volume{punch(0)}; Delete; }{ Volume{100}; Delete; };

// Keep only the contact side: drop the faces in x = 0, y = 0 and the top face z = z_top.
faces() = Boundary{ Volume{quarter(0)}; };
drop() = Surface In BoundingBox{-eps, -eps, z_bottom - eps, eps, half_width + eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_bottom - eps, half_width + eps, eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_top - eps, half_width + eps, half_width + eps, z_top + eps};
keep() = faces();
keep() -= drop();
Delete{ Volume{quarter(0)}; }
Recursive Delete{ Surface{drop()}; }  // with their curves and points not used by kept faces
Physical Surface("punch") = keep();
