// The press line's operations in one case (issue 32, item 2; docs/process-chain.md): one time
// loop runs them in order, time running on.
// - A draw split in two operations is the same draw, bit for bit: the NUMISHEET'93 square cup
//   drawn to 2 mm in one run and as two operations (to 1 mm, then on to 2 mm). A short version
//   of the 40 mm chain of docs/process-chain.md.
// - A gravity operation ends at rest with the blank's weight on the floor (statics: the floor's
//   reaction equals m g), a closing ends when the holder's push reaches its force, and the draw
//   after it starts the punch's motion again from where it stood.
// - A case's operations are checked when it is read, each message naming the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"
#include "model/build_model.hpp"
#include "results/hdf5_file.hpp"
#include "solver/checkpoint.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/formed_part.hpp"
#include "solver/state_fields.hpp"
#include "support/state_bytes.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

fs::path output_folder(const std::string& name) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "operations" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

CaseConfig read(const std::string& case_name, const std::vector<std::string>& set) {
  return read_case(fs::path(SF_SOURCE_DIR) / "cases" / case_name / "case.toml",
                   CaseOptions{.set = set, .stroke = {}, .end_time = {}, .search = {}});
}

struct RunResult {
  RunSummary summary;
  SolutionState state;
};

RunResult run(const Model& model, const fs::path& folder) {
  RunOptions options;
  options.output_directory = folder;
  options.checkpoints = false;
  RunResult r;
  r.summary = run_explicit(model, options, &r.state);
  return r;
}

// Every checkpointed field's key and bytes, but which operation the run is in.
std::map<std::string, std::string> state_bytes(const SolutionState& s) {
  auto bytes = test::state_field_bytes(s, field_role::checkpoint);
  std::erase_if(bytes, [](const auto& entry) { return entry.first.starts_with("operation/"); });
  return bytes;
}

int differing_fields(const SolutionState& a, const SolutionState& b) {
  const auto x = state_bytes(a);
  const auto y = state_bytes(b);
  EXPECT_EQ(x.size(), y.size());
  int differ = 0;
  for (const auto& [key, value] : x) {
    if (y.at(key) != value) {
      ADD_FAILURE() << key << " differs";
      ++differ;
    }
  }
  return differ;
}

const std::string kTwoDraws =
    "operations=[{name=\"draw-1\", kind=\"forming\", stroke=1.0}, "
    "{name=\"draw-2\", kind=\"forming\", stroke=2.0}]";

TEST(Operations, ADrawSplitInTwoOperationsIsTheSameDraw) {
  const RunResult one =
      run(build_model(read("square_cup_aluminium", {"control.stroke=2.0"})), output_folder("one"));
  const fs::path folder = output_folder("two");
  const Model model = build_model(read("square_cup_aluminium", {"control.stroke=0", kTwoDraws}));
  ASSERT_EQ(model.operations.size(), 2u);
  EXPECT_EQ(model.time.end_time, *model.tools[0].motion.time_at_travel(2.0));
  const RunResult two = run(model, folder);
  EXPECT_EQ(differing_fields(one.state, two.state), 0);
  EXPECT_EQ(one.state.cycle, two.state.cycle);
  EXPECT_EQ(two.state.operation.index, 1);
  EXPECT_GT(two.state.contacts[0].stick_force.cwiseAbs().maxCoeff(), 0.0);  // friction acted

  // The first ended at its first whole step at or past 1 mm, the second landed on 2 mm.
  ASSERT_EQ(two.summary.operations.size(), 2u);
  const OperationRecord& first = two.summary.operations[0];
  EXPECT_EQ(first.name, "draw-1");
  EXPECT_EQ(first.kind, "forming");
  const double t1 = *model.tools[0].motion.time_at_travel(1.0);
  EXPECT_GE(first.end_time, t1);
  EXPECT_LT(first.end_time - t1, 2.0 * model.time.time_step);
  EXPECT_EQ(two.summary.operations[1].start_time, first.end_time);
  EXPECT_EQ(two.summary.operations[1].end_time, two.state.time);
  EXPECT_NEAR(two.state.tools[0].travel, 2.0, 1e-9);  // time_at_travel: 1e-12 relative in time

  // Each operation: a group of results.h5 and a formed part; a frame at the first one's end.
  const h5::File file(folder / "results.h5", h5::FileMode::read_only);
  EXPECT_EQ(file.read_attribute_string("/operations/0", "name"), "draw-1");
  EXPECT_EQ(file.read_attribute_double("/operations/0", "end_time"), first.end_time);
  EXPECT_EQ(file.read_attribute_string("/operations/1", "kind"), "forming");
  EXPECT_EQ(first.first_frame, 0);
  EXPECT_GT(first.last_frame, 0);
  EXPECT_EQ(two.summary.operations[1].first_frame, first.last_frame);
  EXPECT_TRUE(fs::exists(operation_formed_part_path(folder, "draw-1")));
  EXPECT_TRUE(fs::exists(operation_formed_part_path(folder, "draw-2")));
  EXPECT_EQ(read_formed_part(operation_formed_part_path(folder, "draw-1")).fields.at("time")[0],
            first.end_time);
}

// verify_bounce: a 10 x 10 x 1 mm steel plate dropped at 1 m/s onto a flat floor (penalty
// 10 N/mm per node). With gravity and damping it comes to rest on the floor, where statics
// asks the floor to carry its weight, m g = 7.85e-7 tonne x 9810 mm/s^2 = 7.701e-3 N. At the
// rest ratio 1e-12 the plate's remaining motion changes the contact force by about 1e-6 of the
// weight (velocity sqrt(1e-12) x 1000 mm/s over w = 7.1e3 rad/s, x 40 N/mm); 1e-4 allowed.
TEST(Operations, GravityEndsAtRestWithTheWeightOnTheFloor) {
  const Model model = build_model(
      read("verify_bounce", {"control.end_time=0", "control.gravity=[0.0, 0.0, -9810.0]",
                             "operations=[{name=\"settle\", kind=\"gravity\", time=0.05, "
                             "rest=1e-12, damping=3000.0}]"}));
  const RunResult r = run(model, output_folder("gravity"));
  ASSERT_EQ(r.summary.operations.size(), 1u);
  EXPECT_NE(r.summary.operations[0].ended_by.find("kinetic energy"), std::string::npos);
  EXPECT_LT(r.state.time, 0.05);
  const double weight = 7.85e-7 * 9810.0;
  EXPECT_NEAR(r.state.tools[0].force.z(), -weight, 1e-5 * weight);
  EXPECT_NEAR(r.state.tools[0].force.x(), 0.0, 1e-9);
}

// The square cup's holder (force-controlled, 4.9 kN ramped in 0.2 ms) closes on the blank with
// the punch out of play; the closing ends when the holder pushes 4 kN. Then the draw: the punch,
// which stood still, starts its motion from its start again, from the closing's end.
TEST(Operations, ClosingByForceThenTheDrawStartsThePunchAgain) {
  const Model model = build_model(
      read("square_cup_aluminium",
           {"control.stroke=0",
            "operations=[{name=\"close\", kind=\"closing\", tools=[\"holder\", \"die\"], "
            "end=\"force\", tool=\"holder\", force=4000.0, time=0.002}, "
            "{name=\"draw\", kind=\"forming\", stroke=1.0}]"}));
  const RunResult r = run(model, output_folder("closing"));
  ASSERT_EQ(r.summary.operations.size(), 2u);
  const OperationRecord& close = r.summary.operations[0];
  EXPECT_NE(close.ended_by.find("push on 'holder'"), std::string::npos) << close.ended_by;
  // The holder's push passes 4 kN while its applied force ramps to 4.9 kN by 0.2 ms.
  EXPECT_GT(close.end_time, 0.0002 * 4000.0 / 4900.0 * 0.5);
  EXPECT_LT(close.end_time, 0.002);
  // The punch stood still through the closing, then travelled 1 mm by its own motion counted
  // from the draw's start: the draw ends (landing) at close.end_time + t(1 mm).
  const double t1 = *model.tools[0].motion.time_at_travel(1.0);
  EXPECT_NEAR(r.state.time, close.end_time + t1, 1e-12 * r.state.time);
  EXPECT_NEAR(r.state.tools[0].travel, 1.0, 1e-9);
  EXPECT_EQ(r.state.tools[0].origin.operation, -1);
  EXPECT_EQ(r.state.tools[0].origin.start, close.end_time);
}

// A run stopped inside either operation and restarted from its checkpoint ends with the bits of
// the run that was not stopped, the operation's state (its start, its end, the punch's restarted
// motion) included.
TEST(Operations, ARestartInsideAnyOperationGivesTheBitsOfTheWholeRun) {
  const Model model = build_model(
      read("square_cup_aluminium",
           {"control.stroke=0",
            "operations=[{name=\"close\", kind=\"closing\", tools=[\"holder\", \"die\"], "
            "end=\"force\", tool=\"holder\", force=4000.0, time=0.002}, "
            "{name=\"draw\", kind=\"forming\", stroke=0.5}]"}));
  const RunResult whole = run(model, output_folder("whole"));
  for (const long stop : {200L, 700L}) {  // the closing ends at cycle 393
    const fs::path folder = output_folder("restart_" + std::to_string(stop));
    RunOptions options;
    options.output_directory = folder;
    options.stop_at_cycle = stop;
    EXPECT_THROW(run_explicit(model, options), RunStopped);
    options.stop_at_cycle = -1;
    options.restart_file = checkpoint_path(folder);
    SolutionState restarted;
    const RunSummary summary = run_explicit(model, options, &restarted);
    EXPECT_EQ(differing_fields(whole.state, restarted), 0) << "stopped at cycle " << stop;
    EXPECT_EQ(restarted.operation.start_time, whole.state.operation.start_time);
    EXPECT_EQ(restarted.operation.end_time, whole.state.operation.end_time);
    ASSERT_EQ(summary.operations.size(), 2u);
    EXPECT_EQ(summary.operations[0].end_time, whole.summary.operations[0].end_time);
  }
}

// The U-channel drawn 2 mm, then its springback as the last operation (the case's [springback],
// implicit): the operation's record, and its formed part is the part as it sprang back.
TEST(Operations, SpringbackIsTheLastOperation) {
  const fs::path folder = output_folder("springback");
  const Model model = build_model(
      read("u_channel_bhf_2450N", {"control.stroke=0",
                                   "operations=[{name=\"draw\", kind=\"forming\", stroke=2.0}, "
                                   "{name=\"release\", kind=\"springback\"}]"}));
  const RunResult r = run(model, folder);
  ASSERT_TRUE(r.summary.springback);
  ASSERT_EQ(r.summary.operations.size(), 2u);
  EXPECT_EQ(r.summary.operations[1].kind, "springback");
  EXPECT_EQ(r.summary.operations[1].start_time, r.summary.operations[0].end_time);
  const FormedPart formed = read_formed_part(formed_part_path(folder));
  const FormedPart sprung = read_formed_part(operation_formed_part_path(folder, "release"));
  EXPECT_NE(formed.fields.at("x"), sprung.fields.at("x"));  // it moved when the tools let go
  EXPECT_EQ(formed.reference_nodes, sprung.reference_nodes);
}

TEST(Operations, AForceThatIsNeverReachedStopsTheRunNamingTheOperation) {
  const Model model = build_model(
      read("square_cup_aluminium",
           {"control.stroke=0",
            "operations=[{name=\"close\", kind=\"closing\", tools=[\"holder\", \"die\"], "
            "end=\"force\", tool=\"holder\", force=1.0e6, time=0.0001}]"}));
  try {
    run(model, output_folder("never"));
    FAIL() << "expected an InstabilityError";
  } catch (const InstabilityError& e) {
    EXPECT_NE(std::string(e.what()).find("operations[0] ('close') did not end within its time"),
              std::string::npos)
        << e.what();
  }
}

std::string read_error(const std::string& case_name, const std::vector<std::string>& set) {
  try {
    build_model(read(case_name, set));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Operations, BadOperationsAreRefusedNamingTheKey) {
  const std::string cup = "square_cup_aluminium";
  EXPECT_NE(read_error(cup, {kTwoDraws})
                .find("control.end_time and control.stroke are for a case "
                      "without [[operations]]"),
            std::string::npos);
  EXPECT_NE(read_error(cup, {"control.stroke=0",
                             "operations=[{name=\"a\", kind=\"forming\", stroke=1.0, "
                             "tools=[\"press\"]}]"})
                .find("operations[0].tools"),
            std::string::npos);
  EXPECT_NE(read_error(
                cup, {"control.stroke=0", "operations=[{name=\"a\", kind=\"gravity\", time=0.01}]"})
                .find("control.gravity set"),
            std::string::npos);
  EXPECT_NE(read_error(cup, {"control.stroke=0",
                             "operations=[{name=\"a\", kind=\"springback\"}, {name=\"b\", "
                             "kind=\"forming\", stroke=1.0}]"})
                .find("only for the last operation"),
            std::string::npos);
  EXPECT_NE(read_error(cup, {"control.stroke=0",
                             "operations=[{name=\"a\", kind=\"forming\", stroke=1.0}, "
                             "{name=\"a\", kind=\"forming\", stroke=2.0}]"})
                .find("a name not used by operations[0]"),
            std::string::npos);
  EXPECT_NE(read_error(cup, {"control.stroke=0",
                             "operations=[{name=\"a\", kind=\"closing\", tool=\"holder\", "
                             "end=\"force\", time=0.01}]"})
                .find("operations[0].force"),
            std::string::npos);
  // A stroke the first operation has passed already.
  EXPECT_NE(read_error(cup, {"control.stroke=0",
                             "operations=[{name=\"a\", kind=\"forming\", stroke=2.0}, "
                             "{name=\"b\", kind=\"forming\", stroke=1.0}]"})
                .find("has passed that travel already"),
            std::string::npos);
  // A gap to a tool the holder never meets moving down (the punch is beside it, not below).
  EXPECT_NE(read_error(cup, {"control.stroke=0",
                             "operations=[{name=\"a\", kind=\"closing\", tool=\"holder\", "
                             "gap_to=\"punch\", gap=0.81, time=0.01}]"})
                .find("never meets tool"),
            std::string::npos);
}

}  // namespace
}  // namespace sf
