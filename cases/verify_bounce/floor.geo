// The rigid floor under the bouncing plate: a 30 x 30 mm square at z = -0.6 (0.1 mm below the
// plate's bottom face, t / 2 = 0.5 mm under its mid-surface), two triangles, normal +z (towards
// the plate). Units: mm. Group: floor.
z = -0.6;
Point(1) = {-10, -10, z};
Point(2) = {20, -10, z};
Point(3) = {20, 20, z};
Point(4) = {-10, 20, z};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{:} = 2;
Transfinite Surface{1};
Physical Surface("floor") = {1};
