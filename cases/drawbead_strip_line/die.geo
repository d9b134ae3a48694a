// The die of the drawbead strip's line model: its face z = 0, flat (the groove is the bead
// line's business). Extruded across the strip (y from -4 to 6).
Point(1) = {-70, -4, 0};
Point(2) = {70, -4, 0};
Line(1) = {1, 2};
Transfinite Curve{1} = 29;
out[] = Extrude {0, 10, 0} { Curve{1}; Layers{2}; };
Physical Surface("die") = {out[1]};
