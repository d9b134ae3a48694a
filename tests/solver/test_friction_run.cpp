// Friction beyond Coulomb through a whole run (docs/contact.md, "Friction laws"): a 10 x 10 x 1
// mm elastic plate pressed onto a flat die by a pressure that ramps p(t) = 1 + 2000 t MPa (1 to 5
// MPa over 2 ms) and slid along x at 100 mm/s. The die's friction is a pressure table
// [2 MPa, 0.15], [4 MPa, 0.10] that does not cover the pressures met. Expected:
//   - the die's tangential reaction equals sum_i mu(p_i) N_i, p_i = N_i / A_i(now) the nodes'
//     contact pressures (every node slides), at every step once the stick springs have loaded;
//   - it follows the closed form mu(p(t)) p(t) A, A = 100 mm^2 (the plate at rest in z: each
//     node's normal force balances the load on its area), up to the plate's small normal
//     dynamics;
//   - the run warns once that pressures below the table's first point were met and once that
//     pressures above its last were, each naming the case, the contact and the value held.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "case_fixture.hpp"
#include "mesh/nodal_area.hpp"
#include "model/blank_parts.hpp"
#include "solver/initial_state.hpp"
#include "solver/step_forces.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

double table_mu(double p) {  // the die's table, held beyond its ends
  return p <= 2.0 ? 0.15 : p >= 4.0 ? 0.10 : 0.15 - 0.05 * (p - 2.0) / 2.0;
}

int count(const std::string& text, const std::string& part) {
  int n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++n;
  }
  return n;
}

TEST(FrictionRun, PressedPlateSlidesWithMuOfItsPressureAndWarnsOnce) {
  const std::string name = "friction_run";
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "die.geo") << test::flat_tool_geo(-10.0, -10.0, 25.0, 20.0, 0.0, 8.0);
  const CaseConfig config = test::write_case(name, test::square_plate_geo(10.0, 0.5, 6),
                                             std::string(test::kElasticSteelSheet) + R"(
[[tools]]
name = "die"
mesh = "die.geo"
group = "plate"
[[contact]]
tool = "die"
friction_pressure_table = [[2.0, 0.15], [4.0, 0.10]]
)" + test::pressed_and_slid(1.0, "[[0.0, 1.0], [2.0e-3, 5.0]]"));
  Model model = build_model(config);
  const ContactPair& pair = model.contacts[0].pair;
  ASSERT_EQ(pair.start_area.size(), model.blank.mesh.nodes.cols());
  SolutionState s = make_initial_state(model);
  testing::internal::CaptureStderr();
  compute_forces(model, s, 0.0);
  double worst_sum = 0.0, worst_closed = 0.0;
  int checked = 0;
  test::run_to_end(model, s, [&](const SolutionState& st) {
    if (st.time < 0.5e-3) {
      return;  // the stick springs load and the plate settles on the die
    }
    const ContactState& c = st.contacts[0];
    double expected = 0.0, normal = 0.0;
    for (Eigen::Index i = 0; i < c.normal_force.size(); ++i) {
      const double area =
          area_now(pair.start_area[i], pair.start_half_thickness[i], st.half_thickness[i]);
      expected += table_mu(c.normal_force[i] / area) * c.normal_force[i];
      normal += c.normal_force[i];
    }
    const double reaction = st.tools[0].force.x();
    worst_sum = std::max(worst_sum, std::abs(reaction - expected) / expected);
    const double p = 1.0 + 2000.0 * st.time;  // the load's pressure now, MPa
    const double closed = table_mu(p) * p * 100.0;
    worst_closed = std::max(worst_closed, std::abs(reaction - closed) / closed);
    ++checked;
    if (checked % 400 == 1) {
      std::printf(
          "t = %.4e s: reaction %.6f N, sum mu(p_i) N_i %.6f N, mu(p) p A %.6f N "
          "(p = %.4f MPa, sum N_i = %.4f N)\n",
          st.time, reaction, expected, closed, p, normal);
    }
  });
  const std::string errors = testing::internal::GetCapturedStderr();
  std::printf("%s", errors.c_str());
  std::printf(
      "%d steps checked: worst relative error %.2e against sum mu(p_i) N_i, %.2e against "
      "mu(p(t)) p(t) A\n",
      checked, worst_sum, worst_closed);
  ASSERT_GT(checked, 100);
  // Every node slides along x: the reaction is sum mu(p_i) N_i to round-off (the nodes' slip
  // along y from the plate's Poisson contraction, a second-order cosine, stays below it).
  EXPECT_LT(worst_sum, 1e-12);
  // The plate's normal dynamics under the ramping load (damped at 2e4 1/s) keep sum N_i within
  // 1 % of p(t) A once settled.
  EXPECT_LT(worst_closed, 0.01);
  const std::string below = "pressure below its first point (2 MPa)";
  const std::string above = "pressure above its last point (4 MPa)";
  EXPECT_EQ(count(errors, below), 1) << errors;
  EXPECT_EQ(count(errors, above), 1) << errors;
  EXPECT_EQ(count(errors, "contact[0] (tool 'die')"), 2) << errors;
  EXPECT_EQ(count(errors, "mu = 0.15 is held constant"), 1) << errors;
  EXPECT_EQ(count(errors, "mu = 0.1 is held constant"), 1) << errors;
  EXPECT_EQ(count(errors, (folder / "case.toml").string()), 2) << errors;
}

}  // namespace
}  // namespace sf
