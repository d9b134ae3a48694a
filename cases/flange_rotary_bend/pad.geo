// The pad: a flat plate on the strip's top surface (z = +0.5) to the die radius's start, x = 37.
Point(1) = {-5, -5, 0.5}; Point(2) = {37, -5, 0.5}; Point(3) = {37, 10, 0.5}; Point(4) = {-5, 10, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh.MeshSizeMax = 1.5;
Physical Surface("pad") = {1};
