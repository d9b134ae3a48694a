// The planar CAD fixture of tests/meshing/test_mesh_import.cpp: a 60 x 40 mm rectangle in z = 0 (a
// blank's outline). plate.step: `gmsh plate.geo -0` (gmsh 4.8.4, OpenCASCADE 7.6).
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 60, 40};
Save "plate.step";
