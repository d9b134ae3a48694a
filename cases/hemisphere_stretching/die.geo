// The die's profile: a torus of tube radius 6.35 mm (the die radius, README.md, grade A) whose top
// circle, radius 59.18 mm (the clamping radius), touches the bottom face of the 0.85 mm blank
// (z = -t / 2). The sheet is clamped there and stretched over the torus's inner upper quarter
// into the die opening (radius 59.18 - 6.35 = 52.83 mm: our reading of the set-up). The torus
// over 100 degrees in plan (the quarter and 5 beyond each symmetry plane), normals outwards
// (upwards and inwards where the blank touches). Units: mm. Group: die.
SetFactory("OpenCASCADE");
Rc = 59.18;       // mm, radius of the torus's centre circle
rd = 6.35;        // mm, die profile radius
z_top = -0.85 / 2;
margin = 5 * Pi / 180;  // rad beyond each symmetry plane
Torus(1) = {0, 0, z_top - rd, Rc, rd, Pi / 2 + 2 * margin};
Rotate {{0, 0, 1}, {0, 0, 0}, -margin} { Volume{1}; }
Physical Surface("die") = {1};  // the torus face (2 and 3 are the sweep's end discs)
