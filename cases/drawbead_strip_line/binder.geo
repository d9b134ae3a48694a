// The binder of the drawbead strip's line model, meshed `lift` above where it stands closed on
// the sheet (its face z = t): flat, the bead is a line on it (case.toml).
t = 1; lift = 4;
Point(1) = {-70, -4, t + lift};
Point(2) = {70, -4, t + lift};
Line(1) = {1, 2};
Transfinite Curve{1} = 29;
out[] = Extrude {0, 10, 0} { Curve{1}; Layers{2}; };
Physical Surface("binder") = {out[1]};
