// Hemispherical punch, radius 50.8 mm (README.md, grade A), its pole touching the top face of the
// 0.85 mm blank (z = t / 2). The lower hemisphere only (contact never reaches the equator at 30 mm
// of travel), over 100 degrees in plan: the quarter model's 90 and 5 beyond each symmetry plane.
// OpenCASCADE surface, normals outwards (towards the blank). Units: mm. Group: punch.
SetFactory("OpenCASCADE");
Rp = 50.8;        // mm
z_pole = 0.85 / 2;
margin = 5 * Pi / 180;  // rad beyond each symmetry plane
Sphere(1) = {0, 0, z_pole + Rp, Rp, -Pi / 2, 0, Pi / 2 + 2 * margin};
Rotate {{0, 0, 1}, {0, 0, 0}, -margin} { Volume{1}; }
Physical Surface("punch") = {1};  // the spherical face (the others are the sweep's flat ends)
