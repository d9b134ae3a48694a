#pragma once
// Shared by the read_case tests: two case texts (minimal, full), text helpers and a fixture that
// writes case files into a fresh temporary folder with empty placeholder mesh files (and an empty
// hardening table flow.csv: read_case checks that it exists; build_model reads it).
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"

namespace sf_test {

namespace fs = std::filesystem;

/// The smallest valid case: only the required keys.
inline constexpr std::string_view kMinimal = R"toml([blank]
mesh = "blank.geo"
thickness = 0.81
material = "steel"

[materials.steel]
density = 7.8e-9
young = 210000
poisson = 0.3

[materials.steel.hardening]
K = 565.3
eps0 = 0.007117
n = 0.2589

[control]
end_time = 0.002
)toml";

/// Every key given, with values that differ from the defaults.
inline constexpr std::string_view kFull = R"toml(title = "NUMISHEET'93 square cup"
units = "m-s-kg-N-Pa"

[blank]
mesh = "geometry/../blank.geo"
group = "sheet"
element_size = 2.5
element = "quad"
thickness = 0.81
integration_points = 7
integration_rule = "lobatto"
material = "aluminium"
formulation = "belytschko_tsay"
hourglass = 0.05
hourglass_form = "stiffness"
rolling_direction = [1, 1, 0]

[materials.aluminium]
type = "von_mises"
density = 2.7e-9
young = 71000.0
poisson = 0.33
forming_limit_curve = [[-0.3, 0.5], [0, 0.22], [0.25, 0.35]]
[materials.aluminium.hardening]
law = "linear"
yield_stress = 150.0
modulus = 300

[materials.rigid_steel]
type = "elastic"
density = 7.8e-9
young = 210000.0
poisson = 0.3

[materials.alu_hill]
type = "hill48"
density = 2.7e-9
young = 70500
poisson = 0.34
r0 = 0.71
r45 = 0.58
r90 = 0.7
[materials.alu_hill.hardening]
law = "tabulated"
file = "data/../flow.csv"

[materials.steel_voce]
density = 7.85e-9
young = 206000.0
poisson = 0.29
[materials.steel_voce.hardening]
law = "voce"
sigma0 = 180.0
Q = 250
b = 12.5

[materials.steel_ludwik]
density = 7.85e-9
young = 210000.0
poisson = 0.3
[materials.steel_ludwik.hardening]
law = "ludwik"
A = 200.0
B = 500
n = 0.3

[[tools]]
name = "die"
mesh = "die.msh"

[[tools]]
name = "punch"
mesh = "punch.geo"
group = "punch_surface"
element_size = 2.0
[tools.motion]
type = "velocity"
direction = [0.0, 0.0, -2.0]
curve = [[0.0, 0.0], [0.001, 2000.0], [0.01, 2000]]

[[tools]]
name = "holder"
mesh = "holder.geo"
group = "binder"
[tools.motion]
type = "displacement"
direction = [1, 1, -1]
curve = [[0, 0]]

[[contact]]
tool = "punch"
search = "modified"
penalty_scale = 0.2
friction = 0.125

[[contact]]
tool = "die"
search = "standard"
projection = "orthogonal"
penalty_stiffness = 500.0
friction_static = 0.2
friction_dynamic = 0.1
friction_decay = 0.05
audit = true

[[boundary]]
group = "sym_x"
type = "symmetry"
axis = "x"

[[boundary]]
group = "sym_y"
type = "symmetry"
axis = "y"

[[boundary]]
group = "clamp"
type = "fixed"

[[draw_in]]
name = "DX"
group = "dx_node"
direction = [-2, 0, 0]
measured = 5.5
measured_stroke = 40.0
source = "Makinouchi et al. 1993"

[[draw_in]]
name = "DD"
group = "dd_node"
direction = [-1, -1, 0]

[control]
end_time = 0
stroke = 15.0
stroke_tool = "holder"
output_frames = 40
history_interval = 50
progress_interval = 1000
time_step_safety = 0.8
mass_scaling_dt = 1e-7
mass_scaling_max_added = 0.05
energy_blowup_ratio = 5
checkpoint_cycles = 5000
checkpoint_minutes = 10.5

[output]
directory = "out/run1"
stress_layers = false

[limits]
max_cycles = 2e6
max_elements = 1e5
max_frames = 50
max_output_gb = 2.5
max_memory_gb = 4
mesh_seconds = 30
max_initial_penetration = 0.1
)toml";

/// The 1-based line of the first occurrence of `needle` in `text`.
inline int line_of(std::string_view text, std::string_view needle) {
  const auto at = text.find(needle);
  if (at == std::string_view::npos) {
    ADD_FAILURE() << "test bug: \"" << needle << "\" not in the case text";
    return -1;
  }
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

/// `text` with the first `from` replaced by `to` (which must be there).
inline std::string replaced(std::string_view text, std::string_view from, std::string_view to) {
  std::string out(text);
  const auto at = out.find(from);
  if (at == std::string::npos) {
    ADD_FAILURE() << "test bug: \"" << from << "\" not in the case text";
    return out;
  }
  return out.replace(at, from.size(), to);
}

inline void expect_contains(const std::string& message, std::string_view part) {
  EXPECT_NE(message.find(part), std::string::npos)
      << "message:  " << message << "\nlacks:    " << part;
}

class ReadCase : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           fmt::format("sf_test_read_case_{}_{}", static_cast<long>(::getpid()), info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (const char* mesh : {"blank.geo", "punch.geo", "die.msh", "holder.geo", "flow.csv"}) {
      std::ofstream(dir_ / mesh) << "";
    }
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write_case(std::string_view text, const fs::path& name = "case.toml") const {
    const fs::path file = dir_ / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }

  /// The message of the InputError that reading `text` must throw (empty if none is thrown).
  std::string error_of(std::string_view text) const {
    const fs::path file = write_case(text);
    try {
      sf::read_case(file);
    } catch (const sf::InputError& error) {
      return error.what();
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return {};
  }

  /// Reading `text` throws an InputError naming the case file (at line `line`, unless 0) and
  /// containing every one of `parts`.
  void expect_error(std::string_view text, int line,
                    std::initializer_list<std::string_view> parts) const {
    const std::string message = error_of(text);
    const std::string file = (dir_ / "case.toml").string();
    expect_contains(message, line > 0 ? fmt::format("{}:{}:", file, line) : file);
    for (const auto part : parts) {
      expect_contains(message, part);
    }
  }

  fs::path dir_;
};

}  // namespace sf_test
