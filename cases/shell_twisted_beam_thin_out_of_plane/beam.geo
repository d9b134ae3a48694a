// Twisted beam (MacNeal & Harder 1985): length 12, width 1.1, twisted by 90 degrees from the
// root (width along y) to the tip (width along z), the helicoid of a straight width line turned
// uniformly about the beam axis x. Structured nw x nl quadrilaterals (4 x 24 by default: the
// customary mesh). Units: the benchmark's consistent set. Groups: blank (surface), root (x = 0,
// clamped), tip (x = 12), tip_ends (its two corner nodes), tip_centre (its middle node).
DefineConstant[ nw = {4, Name "Parameters/elements across"} ];
DefineConstant[ nl = {24, Name "Parameters/elements along"} ];
L = 12; W = 1.1;
Point(1) = {0, -W / 2, 0};
Point(2) = {0, 0, 0};
Point(3) = {0, W / 2, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Transfinite Curve{1, 2} = nw / 2 + 1;
out1[] = Extrude { {L, 0, 0}, {1, 0, 0}, {0, 0, 0}, Pi / 2 } { Curve{1}; Layers{nl}; Recombine; };
out2[] = Extrude { {L, 0, 0}, {1, 0, 0}, {0, 0, 0}, Pi / 2 } { Curve{2}; Layers{nl}; Recombine; };
Coherence;
Physical Surface("blank") = {out1[1], out2[1]};
Physical Curve("root") = {1, 2};
Physical Curve("tip") = {out1[0], out2[0]};
tip_points[] = PointsOf{ Curve{out1[0], out2[0]}; };
Physical Point("tip_centre") = {tip_points[1]};
Physical Point("tip_ends") = {tip_points[0], tip_points[3]};
