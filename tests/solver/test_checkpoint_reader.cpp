// The checkpoint reader (read_checkpoint) against damaged checkpoints: a missing entry, an entry of
// the wrong size, shape or type, a missing or damaged attribute. Each is an sf::InputError (exit 2
// of `sheetform run --restart`) naming the file and the entry; a whole checkpoint reads back.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"
#include "model/build_model.hpp"
#include "results/hdf5_file.hpp"
#include "solver/checkpoint.hpp"
#include "solver/initial_state.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

const Model& bounce() {
  static const Model model =
      build_model(read_case(fs::path(SF_SOURCE_DIR) / "cases/verify_bounce/case.toml"));
  return model;
}

fs::path output_dir() {
  const fs::path dir = fs::path(SF_BINARY_DIR) / "test-output" / "checkpoint_reader";
  fs::create_directories(dir);
  return dir;
}

// A whole checkpoint of the bounce case's initial state, then `damage` done to it.
fs::path damaged(const std::string& name, const std::function<void(h5::File&)>& damage) {
  const fs::path file = output_dir() / (name + ".h5");
  CheckpointInfo info;
  info.case_digest = "0123456789abcdef";
  info.git_hash = "test";
  info.output.run_id = "1-2";
  write_checkpoint(file, make_initial_state(bounce()), info);
  h5::File out(file, h5::FileMode::read_write);
  damage(out);
  out.close();
  return file;
}

// read_checkpoint's message for `file`, which must be an InputError.
std::string refusal(const fs::path& file) {
  SolutionState state = make_initial_state(bounce());
  try {
    read_checkpoint(file, state);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << file << " was read without an InputError";
  return "";
}

void expect_refused(const std::string& name, const std::function<void(h5::File&)>& damage,
                    const std::string& entry) {
  SCOPED_TRACE(name);
  const fs::path file = damaged(name, damage);
  const std::string message = refusal(file);
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  EXPECT_NE(message.find(entry), std::string::npos) << message;
}

TEST(CheckpointReader, ReadsAWholeCheckpointBack) {
  const fs::path file = damaged("whole", [](h5::File&) {});
  SolutionState state = make_initial_state(bounce());
  EXPECT_NO_THROW(read_checkpoint(file, state));
}

TEST(CheckpointReader, DamagedEntriesAreInputErrorsNamingFileAndEntry) {
  expect_refused(
      "missing", [](h5::File& f) { f.remove("/state/v"); }, "/state/v");
  expect_refused(
      "too_short",
      [](h5::File& f) {
        f.remove("/state/x");
        f.write("/state/x", std::vector<double>{1.0, 2.0, 3.0}, {3});
      },
      "/state/x");
  expect_refused(
      "two_dimensional",
      [](h5::File& f) {
        const std::vector<double> x = f.read_doubles("/state/x");
        f.remove("/state/x");
        f.write("/state/x", x, {x.size() / 3, 3});
      },
      "/state/x");
  expect_refused(
      "integers",
      [](h5::File& f) {
        const std::vector<double> mass = f.read_doubles("/state/mass");
        f.remove("/state/mass");
        f.write("/state/mass", std::vector<int>(mass.size(), 1), {mass.size()});
      },
      "/state/mass");
  expect_refused(
      "text",
      [](h5::File& f) {
        f.remove("/state/time");
        f.write_string("/state/time", "noon");
      },
      "/state/time");
  expect_refused(
      "cycle_not_whole",
      [](h5::File& f) {
        f.remove("/state/cycle");
        f.write("/state/cycle", std::vector<double>{1e300}, {1});
      },
      "/state/cycle");
  expect_refused(
      "time_not_a_number",
      [](h5::File& f) {
        f.remove("/state/time");
        f.write("/state/time", std::vector<double>{std::numeric_limits<double>::quiet_NaN()}, {1});
      },
      "/state/time");
}

TEST(CheckpointReader, DamagedAttributesAreInputErrorsNamingFileAndAttribute) {
  expect_refused(
      "no_loop", [](h5::File& f) { f.remove("/loop"); }, "/loop");
  expect_refused(
      "negative_frames", [](h5::File& f) { f.write_attribute("/output", "frames", -3); },
      "/output@frames");
  expect_refused(
      "rows_not_whole", [](h5::File& f) { f.write_attribute("/output", "history_rows", 0.5); },
      "/output@history_rows");
  expect_refused(
      "rows_text",
      [](h5::File& f) { f.write_attribute("/output", "history_rows", std::string("many")); },
      "history_rows");
  expect_refused(
      "audit_missing", [](h5::File& f) { f.write_attribute("/output", "audits", 2); },
      "/output/audit0");
  expect_refused(
      "digest_bytes",
      [](h5::File& f) { f.write_attribute("/", "case_digest", std::string("\x01]\xfe")); },
      "/@case_digest");
}

}  // namespace
}  // namespace sf
