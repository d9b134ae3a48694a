// read_case and format_resolved_case: defaults, every value, every kind of input error (with file,
// key and line in the message) and the resolved-case round trip.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/read_case_fixture.hpp"
#include "core/errors.hpp"

namespace {

namespace fs = std::filesystem;
using namespace sf_test;

TEST_F(ReadCase, MinimalCaseGetsEveryDocumentedDefault) {
  const sf::CaseConfig c = sf::read_case(write_case(kMinimal));
  EXPECT_EQ(c.file, dir_ / "case.toml");
  EXPECT_EQ(c.title, "");
  EXPECT_EQ(c.units, "mm-s-tonne-N-MPa");

  EXPECT_EQ(c.blank.mesh.file, dir_ / "blank.geo");
  EXPECT_EQ(c.blank.mesh.group, "blank");
  EXPECT_EQ(c.blank.mesh.element_size, 0.0);
  EXPECT_EQ(c.blank.element, sf::BlankMeshing::quad);
  EXPECT_EQ(c.blank.thickness, 0.81);
  EXPECT_EQ(c.blank.integration_points, 5);
  EXPECT_EQ(c.blank.integration_rule, sf::ThroughThicknessRule::gauss);
  EXPECT_EQ(c.blank.material, "steel");
  EXPECT_EQ(c.blank.formulation, sf::ShellFormulation::assumed_strain);
  EXPECT_EQ(c.blank.hourglass_coefficient, 0.1);
  EXPECT_EQ(c.blank.hourglass_form, sf::HourglassForm::viscous);
  EXPECT_EQ(c.blank.rolling_direction, (std::array<double, 3>{1.0, 0.0, 0.0}));

  ASSERT_EQ(c.materials.size(), 1u);
  const sf::MaterialConfig& m = c.materials[0];
  EXPECT_EQ(m.name, "steel");
  EXPECT_EQ(m.type, sf::MaterialConfig::Type::von_mises);
  EXPECT_EQ(m.density, 7.8e-9);
  EXPECT_EQ(m.young, 210000.0);  // an integer where a float is expected
  EXPECT_EQ(m.poisson, 0.3);
  EXPECT_EQ(m.hardening.law, sf::HardeningConfig::Law::swift);
  EXPECT_EQ(m.hardening.swift_k, 565.3);
  EXPECT_EQ(m.hardening.swift_eps0, 0.007117);
  EXPECT_EQ(m.hardening.swift_n, 0.2589);
  EXPECT_TRUE(m.forming_limit_curve.empty());  // none
  EXPECT_EQ(&c.blank_material(), &c.materials[0]);

  EXPECT_TRUE(c.tools.empty());
  EXPECT_TRUE(c.contacts.empty());
  EXPECT_TRUE(c.boundaries.empty());
  EXPECT_TRUE(c.draw_ins.empty());
  EXPECT_EQ(c.find_tool("punch"), nullptr);

  EXPECT_EQ(c.control.end_time, 0.002);
  EXPECT_EQ(c.control.stroke, 0.0);
  EXPECT_EQ(c.control.stroke_tool, "");
  EXPECT_EQ(c.control.output_frames, 20);
  EXPECT_EQ(c.control.history_interval, 100);
  EXPECT_EQ(c.control.progress_interval, 0);
  EXPECT_EQ(c.control.time_step_safety, 0.9);
  EXPECT_EQ(c.control.mass_scaling_dt, 0.0);
  EXPECT_EQ(c.control.mass_scaling_max_added, 1.0);
  EXPECT_EQ(c.control.checkpoint_cycles, 0);
  EXPECT_EQ(c.control.checkpoint_minutes, 30.0);
  EXPECT_EQ(c.control.energy_blowup_ratio, 10.0);

  EXPECT_EQ(c.output.directory, (dir_ / "results").string());
  EXPECT_TRUE(c.output.stress_layers);
}

TEST_F(ReadCase, FullCaseReadsEveryValue) {
  const sf::CaseConfig c = sf::read_case(write_case(kFull));
  EXPECT_EQ(c.title, "NUMISHEET'93 square cup");
  EXPECT_EQ(c.units, "m-s-kg-N-Pa");

  EXPECT_EQ(c.blank.mesh.file, dir_ / "blank.geo");  // normalised
  EXPECT_EQ(c.blank.mesh.group, "sheet");
  EXPECT_EQ(c.blank.mesh.element_size, 2.5);
  EXPECT_EQ(c.blank.thickness, 0.81);
  EXPECT_EQ(c.blank.integration_points, 7);
  EXPECT_EQ(c.blank.integration_rule, sf::ThroughThicknessRule::lobatto);
  EXPECT_EQ(c.blank.material, "aluminium");
  EXPECT_EQ(c.blank.hourglass_coefficient, 0.05);
  EXPECT_EQ(c.blank.hourglass_form, sf::HourglassForm::stiffness);
  // [1, 1, 0] normalised: 1/sqrt(2) to round-off (1e-15).
  EXPECT_NEAR(c.blank.rolling_direction[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(c.blank.rolling_direction[1], std::sqrt(0.5), 1e-15);
  EXPECT_EQ(c.blank.rolling_direction[2], 0.0);

  ASSERT_EQ(c.materials.size(), 5u);
  const sf::MaterialConfig& al = c.blank_material();
  EXPECT_EQ(al.name, "aluminium");
  EXPECT_EQ(al.type, sf::MaterialConfig::Type::von_mises);
  EXPECT_EQ(al.density, 2.7e-9);
  EXPECT_EQ(al.young, 71000.0);
  EXPECT_EQ(al.poisson, 0.33);
  EXPECT_EQ(al.hardening.law, sf::HardeningConfig::Law::linear);
  EXPECT_EQ(al.hardening.yield_stress, 150.0);
  EXPECT_EQ(al.hardening.modulus, 300.0);
  EXPECT_EQ(al.forming_limit_curve,
            (std::vector<std::array<double, 2>>{{-0.3, 0.5}, {0.0, 0.22}, {0.25, 0.35}}));
  const auto find = [&](const std::string& name) -> const sf::MaterialConfig* {
    for (const auto& m : c.materials) {
      if (m.name == name) {
        return &m;
      }
    }
    return nullptr;
  };
  const sf::MaterialConfig* steel = find("rigid_steel");
  ASSERT_NE(steel, nullptr);
  EXPECT_EQ(steel->type, sf::MaterialConfig::Type::elastic);
  EXPECT_EQ(steel->young, 210000.0);
  const sf::MaterialConfig* hill = find("alu_hill");
  ASSERT_NE(hill, nullptr);
  EXPECT_EQ(hill->type, sf::MaterialConfig::Type::hill48);
  EXPECT_EQ(hill->young, 70500.0);
  EXPECT_EQ(hill->poisson, 0.34);
  EXPECT_EQ(hill->r0, 0.71);
  EXPECT_EQ(hill->r45, 0.58);
  EXPECT_EQ(hill->r90, 0.7);
  EXPECT_EQ(hill->hardening.law, sf::HardeningConfig::Law::tabulated);
  EXPECT_EQ(hill->hardening.table_file, dir_ / "flow.csv");  // relative to the case, normalised
  const sf::MaterialConfig* voce = find("steel_voce");
  ASSERT_NE(voce, nullptr);
  EXPECT_EQ(voce->type, sf::MaterialConfig::Type::von_mises);
  EXPECT_EQ(voce->r0, 1.0);  // unused default
  EXPECT_EQ(voce->hardening.law, sf::HardeningConfig::Law::voce);
  EXPECT_EQ(voce->hardening.voce_sigma0, 180.0);
  EXPECT_EQ(voce->hardening.voce_q, 250.0);
  EXPECT_EQ(voce->hardening.voce_b, 12.5);
  const sf::MaterialConfig* ludwik = find("steel_ludwik");
  ASSERT_NE(ludwik, nullptr);
  EXPECT_EQ(ludwik->hardening.law, sf::HardeningConfig::Law::ludwik);
  EXPECT_EQ(ludwik->hardening.ludwik_a, 200.0);
  EXPECT_EQ(ludwik->hardening.ludwik_b, 500.0);  // an integer where a float is expected
  EXPECT_EQ(ludwik->hardening.ludwik_n, 0.3);

  ASSERT_EQ(c.tools.size(), 3u);
  const sf::ToolConfig& die = c.tools[0];
  EXPECT_EQ(die.name, "die");
  EXPECT_EQ(die.mesh.file, dir_ / "die.msh");
  EXPECT_EQ(die.mesh.group, "die");  // defaults to the tool's name
  EXPECT_EQ(die.motion.type, sf::MotionConfig::Type::fixed);
  const sf::ToolConfig* punch = c.find_tool("punch");
  ASSERT_EQ(punch, &c.tools[1]);
  EXPECT_EQ(punch->mesh.group, "punch_surface");
  EXPECT_EQ(punch->mesh.element_size, 2.0);
  EXPECT_EQ(punch->motion.type, sf::MotionConfig::Type::velocity);
  EXPECT_EQ(punch->motion.direction, (std::array<double, 3>{0.0, 0.0, -1.0}));
  EXPECT_EQ(punch->motion.curve.times, (std::vector<double>{0.0, 0.001, 0.01}));
  EXPECT_EQ(punch->motion.curve.values, (std::vector<double>{0.0, 2000.0, 2000.0}));
  const sf::ToolConfig& holder = c.tools[2];
  EXPECT_EQ(holder.mesh.group, "binder");
  EXPECT_EQ(holder.motion.type, sf::MotionConfig::Type::displacement);
  const double third = 1.0 / std::sqrt(3.0);
  EXPECT_NEAR(holder.motion.direction[0], third, 1e-15);
  EXPECT_NEAR(holder.motion.direction[1], third, 1e-15);
  EXPECT_NEAR(holder.motion.direction[2], -third, 1e-15);
  EXPECT_EQ(holder.motion.curve.times, (std::vector<double>{0.0}));

  ASSERT_EQ(c.contacts.size(), 2u);
  EXPECT_EQ(c.contacts[0].tool, "punch");
  EXPECT_EQ(c.contacts[0].search, sf::ContactSearchKind::modified);
  EXPECT_EQ(c.contacts[0].penalty_scale, 0.2);
  EXPECT_EQ(c.contacts[0].projection, sf::ContactProjection::interpolated);
  EXPECT_EQ(c.contacts[0].friction_static, 0.125);  // `friction` sets both coefficients
  EXPECT_EQ(c.contacts[0].friction_dynamic, 0.125);
  EXPECT_EQ(c.contacts[0].friction_decay, 0.0);
  EXPECT_EQ(c.contacts[0].penalty_stiffness, 0.0);
  EXPECT_FALSE(c.contacts[0].audit);
  EXPECT_EQ(c.contacts[1].tool, "die");
  EXPECT_EQ(c.contacts[1].search, sf::ContactSearchKind::standard);
  EXPECT_EQ(c.contacts[1].projection, sf::ContactProjection::orthogonal);
  EXPECT_EQ(c.contacts[1].penalty_scale, 0.1);
  EXPECT_EQ(c.contacts[1].penalty_stiffness, 500.0);
  EXPECT_EQ(c.contacts[1].friction_static, 0.2);
  EXPECT_EQ(c.contacts[1].friction_dynamic, 0.1);
  EXPECT_EQ(c.contacts[1].friction_decay, 0.05);
  EXPECT_TRUE(c.contacts[1].audit);

  ASSERT_EQ(c.boundaries.size(), 3u);
  EXPECT_EQ(c.boundaries[0].group, "sym_x");
  EXPECT_EQ(c.boundaries[0].type, sf::BoundaryConfig::Type::symmetry);
  EXPECT_EQ(c.boundaries[0].axis, 0);
  EXPECT_EQ(c.boundaries[1].axis, 1);
  EXPECT_EQ(c.boundaries[2].group, "clamp");
  EXPECT_EQ(c.boundaries[2].type, sf::BoundaryConfig::Type::fixed);

  ASSERT_EQ(c.draw_ins.size(), 2u);
  EXPECT_EQ(c.draw_ins[0].name, "DX");
  EXPECT_EQ(c.draw_ins[0].group, "dx_node");
  EXPECT_EQ(c.draw_ins[0].direction, (std::array<double, 3>{-1.0, 0.0, 0.0}));
  EXPECT_EQ(c.draw_ins[0].measured, 5.5);
  EXPECT_EQ(c.draw_ins[0].measured_stroke, 40.0);
  EXPECT_EQ(c.draw_ins[0].source, "Makinouchi et al. 1993");
  EXPECT_EQ(c.draw_ins[1].measured, -1.0);
  EXPECT_EQ(c.draw_ins[1].measured_stroke, 0.0);
  EXPECT_NEAR(c.draw_ins[1].direction[0], -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(c.draw_ins[1].direction[1], -std::sqrt(0.5), 1e-15);
  EXPECT_EQ(c.draw_ins[1].direction[2], 0.0);

  EXPECT_EQ(c.control.end_time, 0.0);
  EXPECT_EQ(c.control.stroke, 15.0);
  EXPECT_EQ(c.control.stroke_tool, "holder");
  EXPECT_EQ(c.control.output_frames, 40);
  EXPECT_EQ(c.control.history_interval, 50);
  EXPECT_EQ(c.control.progress_interval, 1000);
  EXPECT_EQ(c.control.time_step_safety, 0.8);
  EXPECT_EQ(c.control.mass_scaling_dt, 1e-7);
  EXPECT_EQ(c.control.mass_scaling_max_added, 0.05);
  EXPECT_EQ(c.control.checkpoint_cycles, 5000);
  EXPECT_EQ(c.limits.max_cycles, 2e6);
  EXPECT_EQ(c.limits.max_elements, 1e5);
  EXPECT_EQ(c.limits.max_frames, 50);
  EXPECT_EQ(c.limits.max_output_gb, 2.5);
  EXPECT_EQ(c.limits.max_memory_gb, 4.0);
  EXPECT_EQ(c.limits.mesh_seconds, 30.0);
  EXPECT_EQ(c.limits.max_initial_penetration, 0.1);
  EXPECT_EQ(c.control.checkpoint_minutes, 10.5);
  EXPECT_EQ(c.control.energy_blowup_ratio, 5.0);

  EXPECT_EQ(c.output.directory, (dir_ / "out" / "run1").string());
  EXPECT_FALSE(c.output.stress_layers);
}

TEST_F(ReadCase, StrokeToolDefaultsToTheFirstMovingTool) {
  const std::string text = replaced(kFull, "stroke_tool = \"holder\"\n", "");
  EXPECT_EQ(sf::read_case(write_case(text)).control.stroke_tool, "punch");
}

TEST_F(ReadCase, MissingCaseFileIsAnInputError) {
  const fs::path file = dir_ / "no_such_case.toml";
  try {
    sf::read_case(file);
    ADD_FAILURE() << "no InputError";
  } catch (const sf::InputError& error) {
    expect_contains(error.what(), file.string());
    expect_contains(error.what(), "not found");
  }
}

TEST_F(ReadCase, TomlSyntaxErrorGivesFileLineAndColumn) {
  const std::string text = replaced(kMinimal, "thickness = 0.81", "thickness = = 0.81");
  expect_error(text, line_of(text, "thickness"), {"TOML syntax error"});
}

TEST_F(ReadCase, OutOfRangeMessageHasTheDocumentedForm) {
  const std::string text = replaced(kMinimal, "thickness = 0.81", "thickness = -0.81");
  EXPECT_EQ(error_of(text), fmt::format("{}:{}:13: blank.thickness: expected a number > 0 (mm), "
                                        "got -0.81",
                                        (dir_ / "case.toml").string(), line_of(text, "thickness")));
}

TEST_F(ReadCase, UnknownKeysAreErrorsAtEveryLevel) {
  std::string text = "speed = 3\n" + std::string(kMinimal);
  expect_error(text, 1, {"speed", "unknown key", "title", "control"});

  text = replaced(kMinimal, "thickness = 0.81", "thickness = 0.81\nthicknes = 0.8");
  expect_error(text, line_of(text, "thicknes ="), {"blank.thicknes", "integration_points"});

  text = replaced(kMinimal, "n = 0.2589", "n = 0.2589\nm = 1");
  expect_error(text, line_of(text, "m = 1"), {"materials.steel.hardening.m", "eps0"});

  text = std::string(kMinimal) + "\n[output]\nfolder = \"x\"\n";
  expect_error(text, line_of(text, "folder"), {"output.folder", "stress_layers"});

  text = replaced(kFull, "direction = [1, 1, -1]", "direction = [1, 1, -1]\nspeed = 1");
  expect_error(text, line_of(text, "speed = 1"), {"tools[2].motion.speed", "curve"});
}

TEST_F(ReadCase, WrongTypesAreErrors) {
  std::string text = replaced(kMinimal, "thickness = 0.81", "thickness = \"0.81\"");
  expect_error(text, line_of(text, "thickness"),
               {"blank.thickness", "expected a number > 0 (mm)", "got the string \"0.81\""});

  text = replaced(kMinimal, "thickness = 0.81", "thickness = 0.81\nintegration_points = 5.0");
  expect_error(text, line_of(text, "integration_points"),
               {"blank.integration_points", "an integer in [1, 9]", "got 5.0"});

  text = "title = true\n" + std::string(kMinimal);
  expect_error(text, 1, {"title", "a string", "got true"});

  text = replaced(kFull, "stress_layers = false", "stress_layers = \"no\"");
  expect_error(text, line_of(text, "stress_layers"), {"output.stress_layers", "true or false"});

  text = replaced(kFull, "curve = [[0, 0]]", "curve = [[0, 0, 1]]");
  expect_error(text, line_of(text, "curve = [[0, 0, 1]]"), {"tools[2].motion.curve[0]"});
}

TEST_F(ReadCase, DrawInMeasuredStrokeNeedsAMeasuredValueAndIsNotNegative) {
  std::string text = replaced(kFull, "measured_stroke = 40.0", "measured_stroke = -1.0");
  expect_error(text, line_of(text, "measured_stroke"),
               {"draw_in[0].measured_stroke", ">= 0", "got -1"});
  text =
      replaced(kFull, "direction = [-1, -1, 0]", "direction = [-1, -1, 0]\nmeasured_stroke = 30");
  expect_error(text, line_of(text, "measured_stroke = 30"),
               {"draw_in[1].measured_stroke", "measured"});
}

TEST_F(ReadCase, OutOfRangeValuesAreErrors) {
  struct Edit {
    std::string_view from, to, key, expected;
  };
  const Edit edits[] = {
      {"poisson = 0.3", "poisson = 0.5", "materials.steel.poisson", "(-1, 0.5)"},
      {"n = 0.2589", "n = 1", "materials.steel.hardening.n", "[0, 1)"},
      {"thickness = 0.81", "thickness = 0.81\nintegration_points = 10", "blank.integration_points",
       "[1, 9]"},
      {"thickness = 0.81", "thickness = 0.81\nformulation = \"belytschko_tsay\"\nhourglass = 0.6",
       "blank.hourglass", "[0, 0.5]"},
      {"end_time = 0.002", "end_time = 0.002\ntime_step_safety = 0", "control.time_step_safety",
       "(0, 1]"},
      {"end_time = 0.002", "end_time = 0.002\nenergy_blowup_ratio = 1", "control.energy_blowup",
       "> 1"},
      {"end_time = 0.002", "end_time = 0.002\noutput_frames = 0", "control.output_frames", ">= 1"},
      {"end_time = 0.002", "end_time = -1.0", "control.end_time", ">= 0 (s)"},
      {"end_time = 0.002", "end_time = 0.002\nmass_scaling_max_added = -0.1",
       "control.mass_scaling_max_added", ">= 0"},
  };
  for (const Edit& e : edits) {
    SCOPED_TRACE(e.to);
    const std::string text = replaced(kMinimal, e.from, e.to);
    const auto last_line = e.to.substr(e.to.rfind('\n') + 1);
    expect_error(text, line_of(text, last_line), {e.key, e.expected});
  }
}

TEST_F(ReadCase, MissingRequiredKeysAreErrors) {
  std::string text = replaced(kMinimal, "thickness = 0.81\n", "");
  expect_error(text, line_of(text, "[blank]"), {"blank.thickness", "missing required key"});

  text = replaced(kMinimal, "[control]\nend_time = 0.002\n", "");
  expect_error(text, 0, {"control", "missing required key"});

  text = replaced(kMinimal, "K = 565.3\n", "");
  expect_error(text, line_of(text, "[materials.steel.hardening]"),
               {"materials.steel.hardening.K", "missing"});

  text = replaced(kMinimal, "[materials.steel.hardening]\nK = 565.3\neps0 = 0.007117\nn = 0.2589\n",
                  "");
  expect_error(text, line_of(text, "[materials.steel]"), {"materials.steel.hardening", "missing"});

  text = replaced(kFull, "type = \"displacement\"\n", "");
  expect_error(text, line_of(text, "[tools.motion]\ndirection = [1, 1, -1]"),
               {"tools[2].motion.type", "missing", "\"velocity\""});
}

TEST_F(ReadCase, MeshFilesMustExist) {
  std::string text = replaced(kMinimal, "\"blank.geo\"", "\"geometry/sheet.geo\"");
  expect_error(text, line_of(text, "mesh ="),
               {"blank.mesh", "not found", (dir_ / "geometry" / "sheet.geo").string()});

  text = replaced(kFull, "\"die.msh\"", "\"die.geo\"");
  expect_error(text, line_of(text, "\"die.geo\""), {"tools[0].mesh", (dir_ / "die.geo").string()});

  text = replaced(kMinimal, "\"blank.geo\"", "\"blank.obj\"");
  expect_error(text, line_of(text, "mesh ="), {"blank.mesh", ".geo, .msh, .step"});
}

TEST_F(ReadCase, DanglingNamesAreErrors) {
  std::string text = replaced(kMinimal, "material = \"steel\"", "material = \"steal\"");
  expect_error(text, line_of(text, "material ="), {"blank.material", "\"steal\"", "\"steel\""});

  text = replaced(kFull, "tool = \"die\"", "tool = \"dye\"");
  expect_error(text, line_of(text, "\"dye\""), {"contact[1].tool", "\"dye\"", "\"punch\""});

  text = replaced(kFull, "stroke_tool = \"holder\"", "stroke_tool = \"binder\"");
  expect_error(text, line_of(text, "stroke_tool"), {"control.stroke_tool", "\"binder\""});

  text = replaced(kFull, "stroke_tool = \"holder\"", "stroke_tool = \"die\"");
  expect_error(text, line_of(text, "stroke_tool"), {"control.stroke_tool", "not fixed"});
}

TEST_F(ReadCase, StrokeNeedsAMovingTool) {
  const std::string text = replaced(kMinimal, "end_time = 0.002", "stroke = 15");
  expect_error(text, line_of(text, "stroke = 15"), {"control.stroke", "moving tool"});
}

TEST_F(ReadCase, DuplicateNamesAreErrors) {
  std::string text = replaced(kFull, "name = \"holder\"", "name = \"punch\"");
  expect_error(text, line_of(text, "name = \"punch\"\nmesh = \"holder.geo\""),
               {"tools[2].name", "duplicate", "\"punch\"", "tools[1]"});

  text = replaced(kFull, "tool = \"die\"", "tool = \"punch\"");
  expect_error(text, line_of(text, "tool = \"punch\"\nsearch = \"standard\""),
               {"contact[1].tool", "second [[contact]]", "contact[0]"});
}

TEST_F(ReadCase, CurveTimesMustIncreaseStrictly) {
  std::string text = replaced(kFull, "[0.01, 2000]", "[0.001, 2000]");
  expect_error(text, line_of(text, "[0.001, 2000]]"),
               {"tools[1].motion.curve[2]", "strictly increasing"});

  text = replaced(kFull, "curve = [[0, 0]]", "curve = [[-0.1, 0]]");
  expect_error(text, line_of(text, "[[-0.1, 0]]"), {"tools[2].motion.curve[0]", ">= 0"});

  text = replaced(kFull, "curve = [[0, 0]]", "curve = []");
  expect_error(text, line_of(text, "curve = []"), {"tools[2].motion.curve", "non-empty"});
}

TEST_F(ReadCase, ExactlyOneOfEndTimeAndStroke) {
  std::string text = replaced(kFull, "end_time = 0\n", "end_time = 0.01\n");
  expect_error(text, line_of(text, "stroke = 15.0"),
               {"control.stroke", "exactly one of end_time and stroke"});

  text = replaced(kMinimal, "end_time = 0.002", "end_time = 0");
  expect_error(text, line_of(text, "[control]"), {"end_time", "stroke", "got neither"});
}

TEST_F(ReadCase, KeysThatDoNotApplyAreErrorsNotIgnored) {
  std::string text = replaced(kFull, "poisson = 0.3\n",
                              "poisson = 0.3\n[materials.rigid_steel.hardening]\nK = 1\n");
  expect_error(text, line_of(text, "[materials.rigid_steel.hardening]"),
               {"materials.rigid_steel.hardening", "elastic"});

  text = replaced(kFull, "type = \"fixed\"", "type = \"fixed\"\naxis = \"z\"");
  expect_error(text, line_of(text, "axis = \"z\""), {"boundary[2].axis", "not allowed"});

  text = replaced(kFull, "axis = \"y\"\n", "");
  expect_error(text, line_of(text, "[[boundary]]\ngroup = \"sym_y\""),
               {"boundary[1].axis", "missing", "\"x\", \"y\", \"z\""});

  text = replaced(kFull, "type = \"displacement\"", "type = \"fixed\"");
  expect_error(text, line_of(text, "direction = [1, 1, -1]"),
               {"tools[2].motion.direction", "not allowed"});

  text = replaced(kFull, "search = \"modified\"", "search = \"closest\"");
  expect_error(text, line_of(text, "search ="),
               {"contact[0].search", "\"standard\"", "\"modified\"", "\"cached\""});

  text = replaced(kFull, "friction = 0.125", "friction = 0.125\nfriction_static = 0.2");
  expect_error(text, line_of(text, "friction_static = 0.2\n"),
               {"contact[0].friction_static", "either friction or friction_static"});

  text = replaced(kFull, "friction_dynamic = 0.1", "friction_dynamic = 0.3");
  expect_error(text, line_of(text, "friction_dynamic"), {"contact[1].friction_dynamic", "0.2"});

  text =
      replaced(kFull, "penalty_stiffness = 500.0", "penalty_stiffness = 500.0\npenalty_scale = 1");
  expect_error(text, line_of(text, "penalty_stiffness"),
               {"contact[1].penalty_stiffness", "not both"});

  text = replaced(kFull, "audit = true", "audit = true\nsearch_margin = 1.0");
  expect_error(text, line_of(text, "search_margin"), {"contact[1].search_margin", "cached"});

  text = replaced(kFull, "projection = \"orthogonal\"", "projection = \"normal\"");
  expect_error(text, line_of(text, "projection ="),
               {"contact[1].projection", "\"interpolated\"", "\"orthogonal\""});
}

/// Every field of two cases is the same (the case file itself aside).
void expect_same_case(const sf::CaseConfig& a, const sf::CaseConfig& b) {
  EXPECT_EQ(a.title, b.title);
  EXPECT_EQ(a.units, b.units);
  const auto same_mesh = [](const sf::MeshSourceConfig& x, const sf::MeshSourceConfig& y) {
    EXPECT_EQ(x.file, y.file);
    EXPECT_EQ(x.group, y.group);
    EXPECT_EQ(x.element_size, y.element_size);
  };
  same_mesh(a.blank.mesh, b.blank.mesh);
  EXPECT_EQ(a.blank.element, b.blank.element);
  EXPECT_EQ(a.blank.thickness, b.blank.thickness);
  EXPECT_EQ(a.blank.integration_points, b.blank.integration_points);
  EXPECT_EQ(a.blank.integration_rule, b.blank.integration_rule);
  EXPECT_EQ(a.blank.material, b.blank.material);
  EXPECT_EQ(a.blank.hourglass_coefficient, b.blank.hourglass_coefficient);
  EXPECT_EQ(a.blank.hourglass_form, b.blank.hourglass_form);
  EXPECT_EQ(a.blank.rolling_direction, b.blank.rolling_direction);  // bit for bit
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    const auto &x = a.materials[i], &y = b.materials[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.type, y.type);
    EXPECT_EQ(x.density, y.density);
    EXPECT_EQ(x.young, y.young);
    EXPECT_EQ(x.poisson, y.poisson);
    EXPECT_EQ(x.hardening.law, y.hardening.law);
    EXPECT_EQ(x.hardening.swift_k, y.hardening.swift_k);
    EXPECT_EQ(x.hardening.swift_eps0, y.hardening.swift_eps0);
    EXPECT_EQ(x.hardening.swift_n, y.hardening.swift_n);
    EXPECT_EQ(x.hardening.yield_stress, y.hardening.yield_stress);
    EXPECT_EQ(x.hardening.modulus, y.hardening.modulus);
    EXPECT_EQ(x.hardening.voce_sigma0, y.hardening.voce_sigma0);
    EXPECT_EQ(x.hardening.voce_q, y.hardening.voce_q);
    EXPECT_EQ(x.hardening.voce_b, y.hardening.voce_b);
    EXPECT_EQ(x.hardening.ludwik_a, y.hardening.ludwik_a);
    EXPECT_EQ(x.hardening.ludwik_b, y.hardening.ludwik_b);
    EXPECT_EQ(x.hardening.ludwik_n, y.hardening.ludwik_n);
    EXPECT_EQ(x.hardening.table_file, y.hardening.table_file);
    EXPECT_EQ(x.r0, y.r0);
    EXPECT_EQ(x.r45, y.r45);
    EXPECT_EQ(x.r90, y.r90);
    EXPECT_EQ(x.forming_limit_curve, y.forming_limit_curve);  // bit for bit
  }
  ASSERT_EQ(a.tools.size(), b.tools.size());
  for (std::size_t i = 0; i < a.tools.size(); ++i) {
    const auto &x = a.tools[i], &y = b.tools[i];
    EXPECT_EQ(x.name, y.name);
    same_mesh(x.mesh, y.mesh);
    EXPECT_EQ(x.motion.type, y.motion.type);
    EXPECT_EQ(x.motion.direction, y.motion.direction);
    EXPECT_EQ(x.motion.curve.times, y.motion.curve.times);
    EXPECT_EQ(x.motion.curve.values, y.motion.curve.values);
    EXPECT_EQ(x.motion.mass, y.motion.mass);
    EXPECT_EQ(x.motion.damping, y.motion.damping);
  }
  ASSERT_EQ(a.contacts.size(), b.contacts.size());
  for (std::size_t i = 0; i < a.contacts.size(); ++i) {
    EXPECT_EQ(a.contacts[i].tool, b.contacts[i].tool);
    EXPECT_EQ(a.contacts[i].search, b.contacts[i].search);
    EXPECT_EQ(a.contacts[i].penalty_scale, b.contacts[i].penalty_scale);
    EXPECT_EQ(a.contacts[i].projection, b.contacts[i].projection);
    EXPECT_EQ(a.contacts[i].penalty_stiffness, b.contacts[i].penalty_stiffness);
    EXPECT_EQ(a.contacts[i].friction_static, b.contacts[i].friction_static);
    EXPECT_EQ(a.contacts[i].friction_dynamic, b.contacts[i].friction_dynamic);
    EXPECT_EQ(a.contacts[i].friction_decay, b.contacts[i].friction_decay);
    EXPECT_EQ(a.contacts[i].audit, b.contacts[i].audit);
    EXPECT_EQ(a.contacts[i].search_margin, b.contacts[i].search_margin);
  }
  ASSERT_EQ(a.boundaries.size(), b.boundaries.size());
  for (std::size_t i = 0; i < a.boundaries.size(); ++i) {
    EXPECT_EQ(a.boundaries[i].group, b.boundaries[i].group);
    EXPECT_EQ(a.boundaries[i].type, b.boundaries[i].type);
    EXPECT_EQ(a.boundaries[i].axis, b.boundaries[i].axis);
  }
  ASSERT_EQ(a.draw_ins.size(), b.draw_ins.size());
  for (std::size_t i = 0; i < a.draw_ins.size(); ++i) {
    EXPECT_EQ(a.draw_ins[i].name, b.draw_ins[i].name);
    EXPECT_EQ(a.draw_ins[i].group, b.draw_ins[i].group);
    EXPECT_EQ(a.draw_ins[i].direction, b.draw_ins[i].direction);
    EXPECT_EQ(a.draw_ins[i].measured, b.draw_ins[i].measured);
    EXPECT_EQ(a.draw_ins[i].measured_stroke, b.draw_ins[i].measured_stroke);
    EXPECT_EQ(a.draw_ins[i].source, b.draw_ins[i].source);
  }
  EXPECT_EQ(a.control.end_time, b.control.end_time);
  EXPECT_EQ(a.control.stroke, b.control.stroke);
  EXPECT_EQ(a.control.stroke_tool, b.control.stroke_tool);
  EXPECT_EQ(a.control.output_frames, b.control.output_frames);
  EXPECT_EQ(a.control.history_interval, b.control.history_interval);
  EXPECT_EQ(a.control.progress_interval, b.control.progress_interval);
  EXPECT_EQ(a.control.time_step_safety, b.control.time_step_safety);
  EXPECT_EQ(a.control.mass_scaling_dt, b.control.mass_scaling_dt);
  EXPECT_EQ(a.control.mass_scaling_max_added, b.control.mass_scaling_max_added);
  EXPECT_EQ(a.control.energy_blowup_ratio, b.control.energy_blowup_ratio);
  EXPECT_EQ(a.control.checkpoint_cycles, b.control.checkpoint_cycles);
  EXPECT_EQ(a.control.checkpoint_minutes, b.control.checkpoint_minutes);
  EXPECT_EQ(a.output.directory, b.output.directory);
  EXPECT_EQ(a.output.stress_layers, b.output.stress_layers);
  EXPECT_EQ(a.limits.max_cycles, b.limits.max_cycles);
  EXPECT_EQ(a.limits.max_elements, b.limits.max_elements);
  EXPECT_EQ(a.limits.max_frames, b.limits.max_frames);
  EXPECT_EQ(a.limits.max_output_gb, b.limits.max_output_gb);
  EXPECT_EQ(a.limits.max_memory_gb, b.limits.max_memory_gb);
  EXPECT_EQ(a.limits.mesh_seconds, b.limits.mesh_seconds);
  EXPECT_EQ(a.limits.max_initial_penetration, b.limits.max_initial_penetration);
}

TEST_F(ReadCase, ResolvedCaseReadsBackToTheSameCase) {
  for (const std::string_view text : {kFull, kMinimal}) {
    const sf::CaseConfig original = sf::read_case(write_case(text));
    const std::string resolved = sf::format_resolved_case(original);
    SCOPED_TRACE(resolved);
    EXPECT_EQ(resolved.rfind("# ", 0), 0u);  // starts with the comment header...
    expect_contains(resolved.substr(0, resolved.find('\n')), original.units);  // ...with units
    expect_contains(resolved,
                    fmt::format("\nintegration_points = {}", original.blank.integration_points));
    expect_contains(resolved,
                    fmt::format("\noutput_frames = {}\n", original.control.output_frames));
    expect_contains(resolved, "\nintegration_rule = \"");  // the new keys are written too
    expect_contains(resolved, "\nformulation = \"");
    if (original.blank.formulation == sf::ShellFormulation::belytschko_tsay) {
      expect_contains(resolved, "\nhourglass_form = \"");  // its keys only with its element
    } else {
      EXPECT_EQ(resolved.find("hourglass"), std::string::npos);
    }
    expect_contains(resolved, "\nrolling_direction = [");
    if (text == kFull) {  // written only when given
      expect_contains(resolved, "\nforming_limit_curve = [[-0.3, 0.5], [0.0, 0.22], [0.25, 0.35]]");
    } else {
      EXPECT_EQ(resolved.find("forming_limit_curve"), std::string::npos);
    }
    // Written in another folder: every path in it must already be absolute.
    const sf::CaseConfig again = sf::read_case(write_case(resolved, "results/resolved.toml"));
    expect_same_case(original, again);
  }
}

TEST_F(ReadCase, ResolvedCaseQuotesAwkwardStrings) {
  std::string text =
      replaced(kMinimal, "[blank]", "title = \"a \\\"quoted\\\" \\\\ title\\n\"\n[blank]");
  text = replaced(text, "steel", "mild steel");
  text = replaced(text, "[materials.steel]", "[materials.\"mild steel\"]");
  text = replaced(text, "[materials.steel.hardening]", "[materials.\"mild steel\".hardening]");
  const sf::CaseConfig original = sf::read_case(write_case(text));
  EXPECT_EQ(original.title, "a \"quoted\" \\ title\n");
  const sf::CaseConfig again =
      sf::read_case(write_case(sf::format_resolved_case(original), "resolved.toml"));
  expect_same_case(original, again);
}

}  // namespace
