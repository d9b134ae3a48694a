// Test data: a .geo that declares a parameter and includes its geometry by a relative path
// (include_body.geo, beside it): with parameters, gmsh reads it through a wrapper in another
// folder, and the Include must still resolve here.
DefineConstant[ n = 2 ];
Include "include_body.geo";
