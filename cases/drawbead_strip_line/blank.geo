// A strip drawn through a drawbead: 110 x 2 mm in the plane z = 0.5 (the sheet's mid-surface on
// the die's face z = 0), x from -60 (the tail) to 50 (the pulled end), 0.5 mm elements along it
// (10 over the bead's 4.5 mm mid-surface radius on a 90 degree arc), 2 across.
// Groups: blank, pull (x = 50), tail (x = -60), sides (y = 0 and y = 2: plane strain).
h = 0.5;
Point(1) = {-60, 0, 0.5}; Point(2) = {50, 0, 0.5}; Point(3) = {50, 2, 0.5}; Point(4) = {-60, 2, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 110 / h + 1;
Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("pull") = {2};
Physical Curve("tail") = {4};
Physical Curve("sides") = {1, 3};
