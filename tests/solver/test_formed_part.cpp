// The formed part (solver/formed_part.hpp, issue 32 item 1): written at the end of a run, read by
// another case that continues from it. The chain across cases is checked bitwise: drawing the
// NUMISHEET'93 square cup to 2 mm in one run and as a run to 1 mm (ending at a whole step,
// control.land_on_end = false) continued by a second case from its formed part give the same
// bits in every handed-on field (a short version of the 40 mm chain in docs/process-chain.md).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"
#include "model/build_model.hpp"
#include "results/hdf5_file.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/formed_part.hpp"
#include "solver/initial_state.hpp"
#include "solver/state_fields.hpp"
#include "support/state_bytes.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

fs::path output_folder(const std::string& name) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "formed_part" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

Model square_cup(double stroke_mm, const std::vector<std::string>& set) {
  CaseOptions options{.set = set, .stroke = stroke_mm, .end_time = {}, .search = {}};
  return build_model(
      read_case(fs::path(SF_SOURCE_DIR) / "cases/square_cup_aluminium/case.toml", options));
}

SolutionState run(const Model& model, const fs::path& folder) {
  RunOptions options;
  options.output_directory = folder;
  options.checkpoints = false;
  SolutionState state;
  run_explicit(model, options, &state);
  return state;
}

// Every handed-on field's key and bytes.
std::map<std::string, std::string> handed_on_bytes(const SolutionState& s) {
  return test::state_field_bytes(s, field_role::formed_part);
}

TEST(FormedPart, ChainOfTwoCasesGivesTheBitsOfOneRun) {
  const SolutionState one = run(square_cup(2.0, {}), output_folder("one_run"));
  const fs::path first = output_folder("first");
  run(square_cup(1.0, {"control.land_on_end=false"}), first);
  ASSERT_TRUE(fs::exists(formed_part_path(first)));
  const SolutionState chained =
      run(square_cup(2.0, {"blank.formed_part=\"" + formed_part_path(first).string() + "\""}),
          output_folder("second"));
  ASSERT_GT(chained.cycle, 0);
  const auto a = handed_on_bytes(one);
  const auto b = handed_on_bytes(chained);
  ASSERT_EQ(a.size(), b.size());
  int differ = 0;
  for (const auto& [key, value] : a) {
    if (b.at(key) != value) {
      ADD_FAILURE() << key << " differs between the one run and the chain";
      ++differ;
    }
  }
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(one.cycle, chained.cycle);
  // The stick forces crossed the case boundary (friction 0.162 on every tool).
  EXPECT_GT(chained.contacts[0].stick_force.cwiseAbs().maxCoeff(), 0.0);
}

// A written part reads back with its mesh, names and every field as written.
TEST(FormedPart, ReadsBackWhatWasWritten) {
  const Model model = square_cup(0.3, {});
  const fs::path folder = output_folder("round_trip");
  const SolutionState state = run(model, folder);
  const FormedPart part = read_formed_part(formed_part_path(folder));
  EXPECT_EQ(part.reference_nodes, model.blank.mesh.nodes);
  EXPECT_EQ(part.quads, model.blank.mesh.quads);
  EXPECT_EQ(part.n_points, 5);
  EXPECT_EQ(part.law, "hill48");
  EXPECT_EQ(part.tools, (std::vector<std::string>{"punch", "die", "holder"}));
  EXPECT_EQ(part.contact_tools, (std::vector<std::string>{"punch", "die", "holder"}));
  for (const auto& [key, bytes] : handed_on_bytes(state)) {
    const std::vector<double>& values = part.fields.at(key);
    ASSERT_EQ(bytes.size(), sizeof(double) * values.size()) << key;
    EXPECT_EQ(std::memcmp(bytes.data(), values.data(), bytes.size()), 0) << key;
  }
  EXPECT_EQ(part.fields.at("time").front(), state.time);
  EXPECT_EQ(part.fields.at("cycle").front(), static_cast<double>(state.cycle));
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// A part of format 1 (before tools turned, issue 32 item 7; cases/verify_bounce at t = 1e-5 s,
// written by that build) is read as one whose tools stand unturned: rotation the identity, angle
// and moments zero.
TEST(FormedPart, ReadsAFormatOnePartAsOneWhoseToolsNeverTurned) {
  const FormedPart part = read_formed_part(fs::path(SF_SOURCE_DIR) /
                                           "tests/fuzz/seeds/formed_part/verify_bounce_t1e-5.h5");
  ASSERT_EQ(part.tools.size(), 1u);
  for (int c = 0; c < 9; ++c) {
    const double identity = c % 4 == 0 ? 1.0 : 0.0;
    EXPECT_EQ(part.fields.at("tools/0/rotation" + std::to_string(c)),
              std::vector<double>{identity});
    EXPECT_EQ(part.fields.at("tools/0/previous_rotation" + std::to_string(c)),
              std::vector<double>{identity});
  }
  EXPECT_EQ(part.fields.at("tools/0/angle"), std::vector<double>{0.0});
  EXPECT_EQ(part.fields.at("tools/0/moment2"), std::vector<double>{0.0});
  EXPECT_EQ(part.fields.at("tools/0/travel").size(), 1u);  // read from the file as before
}

TEST(FormedPart, RefusesAnotherVersionAnotherBlankAndOtherFiles) {
  const fs::path folder = output_folder("refusals");
  run(square_cup(0.3, {}), folder);
  const fs::path newer = folder / "newer.h5";
  fs::copy_file(formed_part_path(folder), newer);
  {
    h5::File f(newer, h5::FileMode::read_write);
    f.write_attribute("/", "format_version", 5);
  }
  EXPECT_NE(
      error_of([&] {
        read_formed_part(newer);
      }).find("formed part format 5, this build reads formats 1 to 4 (written by a newer build)"),
      std::string::npos);
  EXPECT_NE(error_of([&] {
              read_formed_part(folder / "results.h5");
            }).find("not a sheetform formed part"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_formed_part(folder / "none.h5"); }).find("no such formed part"),
            std::string::npos);
  // The square cup's part on another blank (the bounce case's plate).
  const Model other =
      build_model(read_case(fs::path(SF_SOURCE_DIR) / "cases/verify_bounce/case.toml"));
  SolutionState s = make_initial_state(other);
  const FormedPart part = read_formed_part(formed_part_path(folder));
  EXPECT_NE(
      error_of([&] { apply_formed_part(part, other, s); }).find("a formed part of another blank"),
      std::string::npos);
  // The same mesh with another law.
  Model j2 = square_cup(0.3, {});
  j2.blank.part.materials[0].law = J2PlaneStress{};
  SolutionState sj = make_initial_state(j2);
  EXPECT_NE(error_of([&] { apply_formed_part(part, j2, sj); }).find("material law hill48"),
            std::string::npos);
}

// A part written by an earlier build (the fuzz seed, format 1) is read by this one and goes on
// the case it came from.
TEST(FormedPart, ReadsAPartOfAnEarlierBuild) {
  const FormedPart part = read_formed_part(fs::path(SF_SOURCE_DIR) /
                                           "tests/fuzz/seeds/formed_part/verify_bounce_t1e-5.h5");
  const Model model =
      build_model(read_case(fs::path(SF_SOURCE_DIR) / "cases/verify_bounce/case.toml"));
  SolutionState s = make_initial_state(model);
  EXPECT_EQ(apply_formed_part(part, model, s), std::vector<std::string>{"floor"});
  EXPECT_GE(s.time, 1e-5);
  EXPECT_GT(s.cycle, 0);
  EXPECT_NE(s.x, model.blank.mesh.nodes);  // the shell moved
}

}  // namespace
}  // namespace sf
