#pragma once
// Writes a small case (a .geo and a case.toml) into the build tree and reads it, for the run-level
// verification tests.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"

namespace sf::test {

/// Writes <build>/test_output/<name>/{blank.geo, case.toml} and reads the case. `case_text` is the
/// case file without its mesh key, which is added as the [blank] table's first line (so
/// `case_text` starts inside [blank]).
inline CaseConfig write_case(const std::string& name, const std::string& geo,
                             const std::string& case_text) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "blank.geo") << geo;
  std::ofstream(folder / "case.toml") << "[blank]\nmesh = \"blank.geo\"\n" << case_text;
  return read_case(folder / "case.toml");
}

/// A flat rectangular tool in the plane z, [x0, x1] x [y0, y1] (mm), as a .geo whose surface is
/// the physical group "plate", meshed at most `size` mm.
inline std::string flat_tool_geo(double x0, double y0, double x1, double y1, double z,
                                 double size) {
  const auto point = [&](int id, double x, double y) {
    return "Point(" + std::to_string(id) + ") = {" + std::to_string(x) + ", " + std::to_string(y) +
           ", " + std::to_string(z) + "};\n";
  };
  return point(1, x0, y0) + point(2, x1, y0) + point(3, x1, y1) + point(4, x0, y1) +
         "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
         "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\nMesh.MeshSizeMax = " +
         std::to_string(size) + ";\nPhysical Surface(\"plate\") = {1};\n";
}

/// A flat square blank [0, side]^2 in the plane z (mm), `nodes` nodes an edge (quads), its surface
/// the physical group "blank", as a .geo.
inline std::string square_plate_geo(double side, double z, int nodes) {
  const std::string s = std::to_string(side), h = std::to_string(z);
  return "Point(1) = {0, 0, " + h + "}; Point(2) = {" + s + ", 0, " + h + "}; Point(3) = {" + s +
         ", " + s + ", " + h + "}; Point(4) = {0, " + s + ", " + h +
         "};\nLine(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
         "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\nTransfinite Curve{1, 2, 3, 4} "
         "= " +
         std::to_string(nodes) +
         ";\nTransfinite Surface{1};\nRecombine Surface{1};\nPhysical Surface(\"blank\") = {1};\n";
}

/// The [blank] keys after its mesh and an elastic steel: a 1 mm sheet (mm, s, tonne, N, MPa).
inline constexpr const char* kElasticSteelSheet = R"(thickness = 1.0
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.3
)";

/// The tables that press the blank by `pressure` MPa on its top face (times the `curve`, a TOML
/// array of [time, factor] points, when not empty) and slide it along x at 100 mm/s for 2 ms
/// (z free), damped at 2e4 1/s: the [[load]], [[prescribed_velocity]] and [control] tables.
inline std::string pressed_and_slid(double pressure, const std::string& curve = {}) {
  return "[[load]]\ngroup = \"blank\"\ntype = \"pressure\"\npressure = " +
         std::to_string(pressure) + "\n" +
         (curve.empty() ? std::string() : "curve = " + curve + "\n") +
         "[[prescribed_velocity]]\ngroup = \"blank\"\nvelocity = [100.0, 0.0, 0.0]\n"
         "components = [\"x\"]\n[control]\nend_time = 2.0e-3\ndamping = 2.0e4\n";
}

/// Central-difference steps from the state until model.time.end_time (no output); calls
/// `after_step(state)` after every step.
template <class AfterStep>
void run_to_end(Model& model, SolutionState& s, AfterStep&& after_step) {
  double dt_previous = 0.0;
  while (s.time < model.time.end_time * (1.0 - 1e-12)) {
    const double dt = std::min(compute_time_step(model, s), model.time.end_time - s.time);
    advance_one_step(model, s, dt, dt_previous);
    dt_previous = dt;
    after_step(s);
  }
}

/// The half-kick energy D = 1/2 sum m |dt/2 a|^2 (N mm) at the end of the step just taken (dt =
/// state.dt): a = F / m from the net force F = f_ext + f_contact - f_int (moments likewise with
/// the rotational inertia), over the components the constraints leave free, without damping (for
/// models without prescribed velocities).
/// Central difference with trapezoidal work increments and the whole-step kinetic energy conserves
/// total - supplied - D exactly at a constant step, for any forces (docs/time-integration.md): D
/// is what the reported balance error carries.
inline double half_kick_energy(const Model& model, const SolutionState& s) {
  const double h = 0.5 * s.dt;
  double d = 0.0;
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) {
    const unsigned held = model.constraints.mask[static_cast<std::size_t>(i)];
    const Vec3 f = s.f_ext.col(i) + s.f_contact.col(i) - s.f_int.col(i);
    const Vec3 m = s.m_ext.col(i) - s.m_int.col(i);
    for (int c = 0; c < 3; ++c) {
      if (!(held & (1u << c))) {
        d += f[c] * f[c] / s.mass[i];
      }
      if (!(held & (1u << (3 + c)))) {
        d += m[c] * m[c] / s.rotational_inertia[i];
      }
    }
  }
  return 0.5 * h * h * d;
}

}  // namespace sf::test
