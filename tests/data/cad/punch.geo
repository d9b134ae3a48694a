// The CAD fixtures of tests/meshing/test_mesh_import.cpp: a punch, a cylinder of radius 25 mm and
// height 40 mm whose bottom (working) edge is rounded by a fillet of radius 5 mm. Its surfaces:
// 1 the side (cylinder, 35 mm high), 2 the fillet (a quarter torus), 3 the top disk (radius 25),
// 4 the bottom disk (radius 20); exact area 2 pi 25 35 + 2 pi 5 (20 pi / 2 + 5) + pi 25^2 +
// pi 20^2 = 9861.9 mm^2.
// punch.step, punch.brep: `gmsh punch.geo -0` (gmsh 4.8.4, OpenCASCADE 7.6). punch.iges (loose
// trimmed faces, as many CAD systems write IGES) and punch_metres.step (the same punch in metres,
// with face names) were written from the same shape by OpenCASCADE's own IGES and STEP writers,
// since gmsh 4.8 writes no IGES.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 40, 25};
e() = Curve In BoundingBox{-26, -26, -0.1, 26, 26, 0.1};
f() = Fillet{1}{e()}{5};
Save "punch.step";
Save "punch.brep";
