// Test data: unit square (OpenCASCADE kernel), transfinite 3 x 3 nodes, not recombined: exactly
// 9 nodes and 8 triangles (two per transfinite cell). Groups: surface "plate", curve "bottom" (y = 0).
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Transfinite Curve{:} = 3;
Transfinite Surface{1};
Physical Surface("plate") = {1};
Physical Curve("bottom") = Curve In BoundingBox{-0.1, -0.1, -0.1, 1.1, 0.1, 0.1};
