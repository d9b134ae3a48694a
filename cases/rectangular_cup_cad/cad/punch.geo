// Rectangular cup (cases/rectangular_cup_cad): the quarter punch as a CAD solid (x >= 0, y >= 0;
// cup axis = z axis). Units: mm. The design: a 70 x 40 mm punch, plan corner radius 10 mm,
// profile radius 6 mm, its flat bottom at z = +0.405 (= t/2, touching the top surface of the
// 0.81 mm blank whose mid-surface is at z = 0), 40 mm high. The punch moves in -z.
//
// This script is the source of ../punch.step (`./make_step.sh`, which runs
// `gmsh cad/punch.geo -0 -o punch.step`): the whole quarter solid is written, a closed shell
// whose faces share their edges. The case takes the contact faces from it by their tags
// (surfaces = [...] in ../case.toml); the physical group "punch" below names the same faces,
// for meshing this script directly (the verification of ../README.md).
SetFactory("OpenCASCADE");

half_x = 35;            // mm
half_y = 20;            // mm
corner_radius = 10;     // mm, in plan
profile_radius = 6;     // mm
z_bottom = 0.81 / 2;    // mm
z_top = 40;             // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;  // elements per 2 pi (the case's curvature_elements)

// Full punch: rounded rectangular prism, then the profile fillet on the bottom edge loop.
Box(1) = {-half_x, -half_y, z_bottom, 2 * half_x, 2 * half_y, z_top - z_bottom};
eps = 1e-6;
vertical_edges() = Curve In BoundingBox{-half_x - eps, -half_y - eps, z_bottom - eps,
                                        half_x + eps, half_y + eps, z_top + eps};
vertical_edges() -= Curve In BoundingBox{-half_x - eps, -half_y - eps, z_bottom - eps,
                                         half_x + eps, half_y + eps, z_bottom + eps};
vertical_edges() -= Curve In BoundingBox{-half_x - eps, -half_y - eps, z_top - eps,
                                         half_x + eps, half_y + eps, z_top + eps};
rounded() = Fillet{1}{vertical_edges()}{corner_radius};
bottom_loop() = Curve In BoundingBox{-half_x - eps, -half_y - eps, z_bottom - eps,
                                     half_x + eps, half_y + eps, z_bottom + eps};
punch() = Fillet{rounded(0)}{bottom_loop()}{profile_radius};

// Quarter: x >= 0, y >= 0.
Box(100) = {0, 0, z_bottom - 1, half_x + 1, half_y + 1, z_top - z_bottom + 2};
quarter() = BooleanIntersection{ Volume{punch(0)}; Delete; }{ Volume{100}; Delete; };

// The contact side: every face but those in x = 0, y = 0 and the top face z = z_top.
faces() = Boundary{ Volume{quarter(0)}; };
drop() = Surface In BoundingBox{-eps, -eps, z_bottom - eps, eps, half_y + eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_bottom - eps, half_x + eps, eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_top - eps, half_x + eps, half_y + eps, z_top + eps};
contact() = faces();
contact() -= drop();
Physical Surface("punch") = contact();
