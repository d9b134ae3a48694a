// Slit annular plate (Sze, Liu & Lo 2004): inner radius 6, outer 10, in the z = 0 plane, slit
// along the positive x-axis; one edge of the slit (theta = 0) clamped, the other (theta = 360
// degrees, at the same place but not joined) lifted by a transverse line force. Structured
// nr x nc quadrilaterals (10 x 80 by default, the paper's mesh: a quarter of nc per quarter
// circle). Units: the benchmark's consistent set. Groups: blank (surface), clamped (theta = 0),
// loaded (theta = 360), loaded_ends (its two end nodes), A (inner corner of the loaded edge),
// B (outer corner).
DefineConstant[ nr = {10, Name "Parameters/elements across"} ];
DefineConstant[ nc = {80, Name "Parameters/elements around"} ];
Ri = 6; Ro = 10;
Point(1) = {0, 0, 0};
// Inner and outer points at 0, 90, 180, 270 degrees, and again at 360 (a separate edge).
For k In {0:4}
  a = k * Pi / 2;
  Point(10 + k) = {Ri * Cos(a), Ri * Sin(a), 0};
  Point(20 + k) = {Ro * Cos(a), Ro * Sin(a), 0};
EndFor
For k In {0:3}
  Circle(10 + k) = {10 + k, 1, 11 + k};   // inner arcs
  Circle(20 + k) = {20 + k, 1, 21 + k};   // outer arcs
EndFor
For k In {0:4}
  Line(30 + k) = {10 + k, 20 + k};         // radial lines; 30 the clamped edge, 34 the loaded one
EndFor
For k In {0:3}
  Curve Loop(k + 1) = {30 + k, 20 + k, -(31 + k), -(10 + k)};
  Plane Surface(k + 1) = {k + 1};
  Transfinite Curve{10 + k, 20 + k} = nc / 4 + 1;
  Transfinite Surface{k + 1};
  Recombine Surface{k + 1};
EndFor
Transfinite Curve{30:34} = nr + 1;
Physical Surface("blank") = {1, 2, 3, 4};
Physical Curve("clamped") = {30};
Physical Curve("loaded") = {34};
Physical Point("loaded_ends") = {14, 24};
Physical Point("A") = {14};
Physical Point("B") = {24};
