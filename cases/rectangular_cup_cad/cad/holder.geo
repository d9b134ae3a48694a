// Rectangular cup (cases/rectangular_cup_cad): the quarter blank holder as a CAD solid (x >= 0,
// y >= 0; cup axis = z axis). Units: mm. The design: a 10 mm plate whose flat bottom face at
// z = +0.405 (= t/2, touching the top surface of the 0.81 mm blank whose mid-surface is at z = 0)
// has an opening 1 mm larger than the die's (76 x 46 mm, plan corner radius 13 mm) and reaches
// out to x = 70, y = 55.
//
// This script is the source of ../holder.step (`./make_step.sh`, which runs
// `gmsh cad/holder.geo -0 -o holder.step`): the whole quarter solid is written. The case takes
// its bottom face by its tag (surfaces = [...] in ../case.toml); the physical group "holder" below
// names the same face, for meshing this script directly (../README.md).
SetFactory("OpenCASCADE");

half_x = 37 + 1;        // mm, the die opening + 1 mm
half_y = 22 + 1;        // mm
corner_radius = 12 + 1; // mm, in plan
outer_x = 70;           // mm
outer_y = 55;           // mm
z_face = 0.81 / 2;      // mm
height = 10;            // mm
If (Mesh.MeshSizeMax >= 1e21)
  Mesh.MeshSizeMax = 2;
EndIf
Mesh.MeshSizeFromCurvature = 32;  // elements per 2 pi (the case's curvature_elements)

Box(1) = {0, 0, z_face, outer_x, outer_y, height};
Box(2) = {-half_x, -half_y, z_face - 1, 2 * half_x, 2 * half_y, height + 2};
eps = 1e-6;
vertical_edges() = Curve In BoundingBox{-half_x - eps, -half_y - eps, z_face - 1 - eps,
                                        half_x + eps, half_y + eps, z_face + height + 1 + eps};
vertical_edges() -= Curve In BoundingBox{-half_x - eps, -half_y - eps, z_face - 1 - eps,
                                         half_x + eps, half_y + eps, z_face - 1 + eps};
vertical_edges() -= Curve In BoundingBox{-half_x - eps, -half_y - eps, z_face + height + 1 - eps,
                                         half_x + eps, half_y + eps, z_face + height + 1 + eps};
opening() = Fillet{2}{vertical_edges()}{corner_radius};
quarter() = BooleanDifference{ Volume{1}; Delete; }{ Volume{opening(0)}; Delete; };

// The contact side: the bottom face z = z_face.
contact() = Surface In BoundingBox{-eps, -eps, z_face - eps, outer_x + eps, outer_y + eps,
                                   z_face + eps};
Physical Surface("holder") = contact();
