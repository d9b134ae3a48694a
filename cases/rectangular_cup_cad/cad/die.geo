// Rectangular cup (cases/rectangular_cup_cad): the quarter die as a CAD solid (x >= 0, y >= 0;
// cup axis = z axis). Units: mm. The design: a 74 x 44 mm opening (2 mm clearance per side on the
// 70 x 40 mm punch), plan corner radius 12 mm, profile radius 6 mm rounding the top face into the
// opening; the top face at z = -0.405 (= -t/2, touching the bottom surface of the 0.81 mm blank
// whose mid-surface is at z = 0), out to x = 70, y = 55 (beyond the 65 x 50 mm quarter blank);
// 40 mm deep.
//
// This script is the source of ../die.step (`./make_step.sh`, which runs
// `gmsh cad/die.geo -0 -o die.step`): the whole quarter solid is written. The case takes the
// contact faces from it by their tags (surfaces = [...] in ../case.toml); the physical group
// "die" below names the same faces, for meshing this script directly (../README.md).
SetFactory("OpenCASCADE");

half_x = 37;            // mm, half the opening along x
half_y = 22;            // mm, half the opening along y
corner_radius = 12;     // mm, in plan
profile_radius = 6;     // mm
outer_x = 70;           // mm, quarter extent in x
outer_y = 55;           // mm, quarter extent in y
z_top = -0.81 / 2;      // mm
z_bottom = -40;         // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;  // elements per 2 pi (the case's curvature_elements)

// Full die: a plate with a rounded-rectangle opening, then the profile fillet on the opening edge.
Box(1) = {-outer_x, -outer_y, z_bottom, 2 * outer_x, 2 * outer_y, z_top - z_bottom};
Box(2) = {-half_x, -half_y, z_bottom - 1, 2 * half_x, 2 * half_y, z_top - z_bottom + 2};
eps = 1e-6;
vertical_edges() = Curve In BoundingBox{-half_x - eps, -half_y - eps, z_bottom - 1 - eps,
                                        half_x + eps, half_y + eps, z_top + 1 + eps};
vertical_edges() -= Curve In BoundingBox{-half_x - eps, -half_y - eps, z_bottom - 1 - eps,
                                         half_x + eps, half_y + eps, z_bottom - 1 + eps};
vertical_edges() -= Curve In BoundingBox{-half_x - eps, -half_y - eps, z_top + 1 - eps,
                                         half_x + eps, half_y + eps, z_top + 1 + eps};
opening() = Fillet{2}{vertical_edges()}{corner_radius};
plate() = BooleanDifference{ Volume{1}; Delete; }{ Volume{opening(0)}; Delete; };
opening_edge() = Curve In BoundingBox{-half_x - eps, -half_y - eps, z_top - eps,
                                      half_x + eps, half_y + eps, z_top + eps};
die() = Fillet{plate(0)}{opening_edge()}{profile_radius};

// Quarter: x >= 0, y >= 0.
Box(100) = {0, 0, z_bottom - 1, outer_x + 1, outer_y + 1, z_top - z_bottom + 2};
quarter() = BooleanIntersection{ Volume{die(0)}; Delete; }{ Volume{100}; Delete; };

// The contact side: every face but those in x = 0, y = 0, x = outer_x, y = outer_y and the
// bottom face z = z_bottom.
faces() = Boundary{ Volume{quarter(0)}; };
drop() = Surface In BoundingBox{-eps, -eps, z_bottom - eps, eps, outer_y + eps, z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_bottom - eps, outer_x + eps, eps, z_top + eps};
drop() += Surface In BoundingBox{outer_x - eps, -eps, z_bottom - eps, outer_x + eps, outer_y + eps,
                                 z_top + eps};
drop() += Surface In BoundingBox{-eps, outer_y - eps, z_bottom - eps, outer_x + eps, outer_y + eps,
                                 z_top + eps};
drop() += Surface In BoundingBox{-eps, -eps, z_bottom - eps, outer_x + eps, outer_y + eps,
                                 z_bottom + eps};
contact() = faces();
contact() -= drop();
Physical Surface("die") = contact();
