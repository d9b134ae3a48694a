// A drawbead line in a run (docs/drawbeads.md): a 1 mm steel strip, 10 mm wide, between a flat
// die and a flat binder closed on it, pulled 1 mm through a bead line across it. With 1 mm
// elements and a 4 mm bead width the window's sum is exact (tests/contact/test_drawbead.cpp),
// so once the strip slides the bead holds it back with exactly F_r x 10 mm, which the binder
// feels as its reaction, and pushes it onto the die with F_u x 10 mm, which the binder feels as
// an opening force. The slip work is the restraint times the distance slid, and the energy
// balance stays closed with the bead's work counted in the contact's. Bad bead lines are
// refused with the case, the bead and what was expected.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "case_fixture.hpp"
#include "core/errors.hpp"
#include "support/expect_input_error.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

constexpr double kRestraint = 50.0;  // N/mm
constexpr double kUplift = 20.0;     // N/mm
constexpr double kWidth = 10.0;      // mm, the strip's

const std::string kStrip = R"(
Point(1) = {0, 0, 0}; Point(2) = {60, 0, 0}; Point(3) = {60, 10, 0}; Point(4) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 61;
Transfinite Curve{2, 4} = 11;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("pull") = {2};
)";

// The strip's case with `bead` as its [[drawbeads]] table (empty: none).
CaseConfig strip_case(const std::string& name, const std::string& bead) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "die.geo") << test::flat_tool_geo(-10.0, -10.0, 80.0, 20.0, -0.5, 15.0);
  std::ofstream(folder / "binder.geo") << test::flat_tool_geo(-10.0, -10.0, 80.0, 20.0, 0.5, 15.0);
  return test::write_case(name, kStrip, std::string(test::kElasticSteelSheet) + R"([[tools]]
name = "die"
mesh = "die.geo"
group = "plate"
[[tools]]
name = "binder"
mesh = "binder.geo"
group = "plate"
[[contact]]
tool = "die"
[[contact]]
tool = "binder"
[[prescribed_velocity]]
group = "pull"
velocity = [1000.0, 0.0, 0.0]
components = ["x"]
curve = [[0.0, 0.0], [2.0e-4, 1.0]]
[control]
end_time = 1.2e-3
)" + bead);
}

const std::string kBead = fmt::format(R"(
[[drawbeads]]
name = "bead"
tool = "binder"
line = [[30.0, -5.0, 0.5], [30.0, 15.0, 0.5]]
width = 4.0
height = 1.0
closure = [0.0, 1.0]
restraining_force = [0.0, {}]
uplift_force = [0.0, {}]
)",
                                      kRestraint, kUplift);

TEST(DrawbeadRun, PulledStripFeelsTheBeadForceTimesItsWidth) {
  const CaseConfig config = strip_case("drawbead_pull", kBead);
  Model model = build_model(config);
  ASSERT_EQ(model.drawbeads.size(), 1u);
  SolutionState s = make_initial_state(model);
  compute_forces(model, s, 0.0);
  double pulled_force_sum = 0.0;  // the binder's x force, averaged over the last 0.5 mm
  double uplift_sum = 0.0;
  int samples = 0;
  double max_balance = 0.0;
  test::run_to_end(model, s, [&](const SolutionState& st) {
    if (st.time > 0.2e-3) {  // past the first steps' small energies
      max_balance = std::max(max_balance, std::abs(st.energies.balance_error()));
    }
    if (st.time > 0.7e-3) {
      pulled_force_sum += st.tools[1].force.x();
      uplift_sum += st.tools[1].force.z();
      ++samples;
    }
  });
  const double pull = pulled_force_sum / samples;
  const double uplift = uplift_sum / samples;
  std::printf(
      "energies at the end: total %.4f, supplied %.4f, contact %.4f, kinetic %.4f, "
      "internal %.4f, external %.4f N mm\n",
      s.energies.total(), s.energies.supplied(), s.energies.contact, s.energies.kinetic,
      s.energies.internal, s.energies.external_work);
  std::printf(
      "binder's mean force over the last 0.5 mm: x %.4f N (F_r W = %.1f N), z %.4f N; bead "
      "work %.4f N mm; largest |balance error| %.2e\n",
      pull, kRestraint * kWidth, uplift, s.energies.drawbead_work, max_balance);
  // Sliding nodes give the limits' sum exactly; nodes that stick for a step (the strip's
  // elastic waves) lower the mean: 1 % allowed.
  EXPECT_NEAR(pull, kRestraint * kWidth, 0.01 * kRestraint * kWidth);
  // The bead's own reaction at the end (the binder's z force also carries its contact's): the
  // uplift times the width, less what the strip's press into the die (a few micrometres of the
  // 1 mm closing travel) takes off the closure.
  DrawbeadState copy = s.drawbeads[0];
  Matrix3X f = Matrix3X::Zero(3, s.x.cols());
  const ContactKinematics still{.x = s.x,
                                .v = s.v,
                                .half_thickness = s.half_thickness,
                                .tool_displacement = Vec3::Zero(),
                                .tool_displacement_increment = Vec3::Zero(),
                                .dt = 0.0};
  const DrawbeadResult bead = compute_drawbead_forces(model.drawbeads[0].line, copy, still, f);
  std::printf("the bead's reaction at the end: (%.4f, %.4f, %.4f) N\n", bead.force_on_tool.x(),
              bead.force_on_tool.y(), bead.force_on_tool.z());
  EXPECT_NEAR(bead.force_on_tool.z(), kUplift * kWidth, 0.01 * kUplift * kWidth);
  EXPECT_GT(uplift, bead.force_on_tool.z() * 0.99);  // the binder carries it
  // The slip work: the restraint over the distance slid, the pulled end's 1.1 mm (0.1 mm in the
  // ramp) less the strip's stretch between bead and end (500 N x 30 mm / (E x 10 mm^2) =
  // 0.007 mm); the first steps, before the bead's springs fill, take a little more.
  const double slid = 1.1 - kRestraint * kWidth * 30.0 / (210000.0 * kWidth * 1.0);
  EXPECT_NEAR(s.energies.drawbead_work, kRestraint * kWidth * slid,
              0.02 * kRestraint * kWidth * slid);
  EXPECT_LT(max_balance, 1e-2);
}

TEST(DrawbeadRun, LineFromAGeoCurveIsThePolylinesLine) {
  // The same line as kBead's, drawn in a .geo as a Physical Curve: the laid line is the same.
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "drawbead_geo";
  fs::create_directories(folder);
  std::ofstream(folder / "bead.geo") << R"(
Point(1) = {30, -5, 0.5}; Point(2) = {30, 5, 0.5}; Point(3) = {30, 15, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3};
Physical Curve("bead") = {1, 2};
)";
  std::string from_file = kBead;
  const std::string polyline = "line = [[30.0, -5.0, 0.5], [30.0, 15.0, 0.5]]";
  from_file.replace(from_file.find(polyline), polyline.size(), "line_file = \"bead.geo\"");
  const Model by_points = build_model(strip_case("drawbead_geo", kBead));
  const Model by_file = build_model(strip_case("drawbead_geo", from_file));
  const DrawbeadLine& a = by_points.drawbeads[0].line;
  const DrawbeadLine& b = by_file.drawbeads[0].line;
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t k = 0; k < a.points.size(); ++k) {
    EXPECT_NEAR((a.points[k] - b.points[k]).norm(), 0.0, 1e-9) << k;
  }
  EXPECT_NEAR(b.length(), 20.0, 1e-9);
  // A closed curve is not a bead line.
  std::ofstream(folder / "loop.geo") << R"(
Point(1) = {30, -5, 0.5}; Point(2) = {40, -5, 0.5}; Point(3) = {30, 15, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Physical Curve("bead") = {1, 2, 3};
)";
  std::string loop = from_file;
  loop.replace(loop.find("bead.geo"), 8, "loop.geo");
  const CaseConfig closed = strip_case("drawbead_geo", loop);
  test::expect_input_error([&] { build_model(closed); },
                           {"drawbeads[0].line_file", "curve group 'bead'", "the line is closed"});
}

TEST(DrawbeadRun, BadBeadLinesAreRefused) {
  // A line that misses the binder (10 mm above it).
  const std::string off = fmt::format(R"(
[[drawbeads]]
name = "high"
tool = "binder"
line = [[30.0, -5.0, 10.5], [30.0, 15.0, 10.5]]
width = 4.0
height = 1.0
closure = [0.0, 1.0]
restraining_force = [0.0, 50.0]
)");
  const CaseConfig config = strip_case("drawbead_off", off);
  test::expect_input_error([&] { build_model(config); },
                           {"drawbeads[0] (high)", "point 1", "10 mm", "misses the tool"});
  // The case's own refusals, each naming the key.
  const auto refuses = [](const std::string& name, const std::string& bead,
                          std::vector<std::string> words) {
    test::expect_input_error([&] { strip_case(name, bead); }, std::move(words));
  };
  const std::string head = R"(
[[drawbeads]]
name = "b"
tool = "binder"
line = [[30.0, -5.0, 0.5], [30.0, 15.0, 0.5]]
width = 4.0
height = 1.0
)";
  refuses("drawbead_closure_range", head + "closure = [0.0, 1.5]\nrestraining_force = [0.0, 5.0]\n",
          {"drawbeads[0].closure", "1.5"});
  refuses("drawbead_not_function",
          head + "closure = [0.0, 0.5, 0.5]\nrestraining_force = [0.0, 5.0, 6.0]\n",
          {"drawbeads[0].closure", "function of the closure"});
  refuses("drawbead_lengths", head + "closure = [0.0, 1.0]\nrestraining_force = [5.0]\n",
          {"drawbeads[0].restraining_force", "one per `closure`"});
  refuses("drawbead_no_curve", head, {"drawbeads[0]", "closure"});
  refuses("drawbead_locking_limit",
          head + "locking = true\nclosure = [0.0, 1.0]\nrestraining_force = [0.0, 5.0]\n",
          {"drawbeads[0].restraining_force", "locking"});
  std::string punch = head + "closure = [0.0, 1.0]\nrestraining_force = [0.0, 5.0]\n";
  punch.replace(punch.find("\"binder\""), 8, "\"punch\"");
  refuses("drawbead_tool", punch, {"drawbeads[0].tool", "[[tools]]"});
  refuses("drawbead_round_keys",
          head + "closure = [0.0, 1.0]\nrestraining_force = [0.0, 5.0]\n" + "bead_radius = 4.0\n",
          {"drawbeads[0].bead_radius", "round_bead"});
  refuses("drawbead_one_point",
          "\n[[drawbeads]]\nname = \"b\"\ntool = \"binder\"\nline = [[30.0, -5.0, 0.5]]\n"
          "width = 4.0\nheight = 1.0\nclosure = [0.0, 1.0]\nrestraining_force = [0.0, 5.0]\n",
          {"drawbeads[0].line", "at least 2 points"});
}

TEST(DrawbeadRun, RoundBeadNeedsItsFrictionWithAPressureDependentContact) {
  // A round bead takes the binder contact's dynamic coefficient unless it has its own; a contact
  // whose coefficient depends on the pressure has none to give: refused, naming the bead and the
  // tool; with the bead's own friction it builds.
  const std::string round = R"(
[[drawbeads]]
name = "round"
tool = "binder"
line = [[30.0, -5.0, 0.5], [30.0, 15.0, 0.5]]
width = 4.0
force = "round_bead"
bead_radius = 4.0
shoulder_radius = 4.0
depth = 4.0
flow_stress = 300.0
)";
  CaseConfig config = strip_case("drawbead_round_pressure_friction", round);
  config.contacts[1].friction_pressure_table = {{{1.0, 0.12}}, {{10.0, 0.1}}};
  test::expect_input_error(
      [&] { build_model(config); },
      {"drawbeads[0] (round)", "tool 'binder'", "pressure-dependent", "give the bead's friction"});
  config.drawbeads[0].friction = 0.1;
  EXPECT_NO_THROW(build_model(config));
}

}  // namespace
}  // namespace sf
