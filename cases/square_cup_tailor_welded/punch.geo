// NUMISHEET'93 square cup: half of the rigid punch (y >= 0; cup axis = z axis), for the
// tailor-welded blank. Units: mm. Only the contact side: the flat bottom face at z = +0.6 (half
// the thick sheet's 1.2 mm: it touches the thick side's top surface; the thin side's is 0.2 mm
// lower), the 8 mm profile radius and the side walls up to z = 60. The faces in the symmetry plane
// and the top face are removed. The punch moves in -z.
// Source: NUMISHEET'93 benchmark specification, values as listed in ../../docs/references.md:
// punch 70 x 70 mm, plan corner radius 10 mm, profile radius 8 mm (grade C).
// Mesh normals point out of the tool (OCC solid faces are meshed with outward normals).
// Mesh: 3-node triangles, Mesh.MeshSizeMax when the caller sets it, else 2 mm; refined on the
// profile radius (32 elements per 2 pi of curvature).
SetFactory("OpenCASCADE");

half_width = 35;        // mm
corner_radius = 10;     // mm, in plan
profile_radius = 8;     // mm
z_bottom = 1.2 / 2;     // mm
z_top = 60;             // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;

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

// Half: y >= 0.
Box(100) = {-half_width - 1, 0, z_bottom - 1, 2 * half_width + 2, half_width + 1,
            z_top - z_bottom + 2};
half() = BooleanIntersection{ Volume{punch(0)}; Delete; }{ Volume{100}; Delete; };

faces() = Boundary{ Volume{half(0)}; };
drop() = Surface In BoundingBox{-half_width - eps, -eps, z_bottom - eps, half_width + eps, eps,
                                z_top + eps};
drop() += Surface In BoundingBox{-half_width - eps, -eps, z_top - eps, half_width + eps,
                                 half_width + eps, z_top + eps};
keep() = faces();
keep() -= drop();
Delete{ Volume{half(0)}; }
Recursive Delete{ Surface{drop()}; }
Physical Surface("punch") = keep();
