// The flanging steel: a flat plate on the strip's top surface (z = +0.5) from x = 37 on, 4 mm
// (the die radius plus the thickness) from the hinge at (37, y, -3.5), the die radius's centre.
Point(1) = {37, -5, 0.5}; Point(2) = {75, -5, 0.5}; Point(3) = {75, 10, 0.5}; Point(4) = {37, 10, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh.MeshSizeMax = 1.5;
Physical Surface("steel") = {1};
