// The die: a flat top at z = -0.5 (the strip's underside) to x = 37, a 3 mm radius centred at
// (37, -3.5) down to the wall x = 40, drawn back 1 mm over its 36.5 mm (1.6 degrees) so that
// it does not pinch the flange against the steel. Meshed as triangles, 0.4 mm on the radius.
Point(1) = {-5, -5, -0.5, 1.5};
Point(2) = {37, -5, -0.5, 0.4};
Point(3) = {37, -5, -3.5, 0.4};
Point(4) = {40, -5, -3.5, 0.4};
Point(5) = {39, -5, -40, 1.5};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Line(3) = {4, 5};
top[] = Extrude {0, 15, 0} { Curve{1}; };
radius[] = Extrude {0, 15, 0} { Curve{2}; };
wall[] = Extrude {0, 15, 0} { Curve{3}; };
Mesh.MeshSizeMax = 1.5;
Physical Surface("die") = {top[1], radius[1], wall[1]};
