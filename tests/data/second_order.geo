// Test data: unit square meshed with second-order (6-node) triangles: not supported by the reader.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Mesh.ElementOrder = 2;
Mesh.MeshSizeMax = 0.5;
Physical Surface("plate") = {1};
