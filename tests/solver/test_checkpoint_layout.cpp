// The checkpoint's layout, format 5, pinned (format 1 before the operations of issue 32, item 2; 2
// before the tools' turns, item 7; 3 before the contact's results, issue 33, item 4; 4 before the
// contact's front bounds, issue 34, item 3)
// (issue 32, item 1: the state's fields are to be described once, and the checkpoint's list
// generated from that description). The writer and the reader walk the same list, so a renamed,
// reordered, dropped or re-typed entry still reads back and restart_bitwise cannot see it; a
// checkpoint written by an earlier build then fails to read. This test compares what
// visit_checkpoint_fields visits, in order (kind, name, type or width per node / element), for two
// cases with every kind of state, against tests/data/checkpoint_layout_v5.txt. A deliberate change
// of the layout is a new format version (src/solver/checkpoint.cpp, kFormatVersion) with a new
// file, written by running this test with SF_WRITE_CHECKPOINT_LAYOUT=1.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>

#include "casefile/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/checkpoint_fields.hpp"
#include "solver/initial_state.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

// Writes one line per visited entry: "scalar NAME TYPE", "nodes NAME WIDTH" (values per node),
// "elements NAME WIDTH" (values per element; 0 for an array the case leaves empty). The initial
// state is recorded: the contacts' arrays (stick forces, distance bounds) are sized at the first
// search and show width 0 here, so only their names, order and kind are pinned (restart_bitwise
// proves their contents cross a restart).
class LayoutRecorder {
 public:
  explicit LayoutRecorder(long n_nodes) : n_nodes_(n_nodes) {}
  template <class T>
  void scalar(const std::string& name, const T&) {
    out_ << "scalar " << name << ' ' << type_name<T>() << '\n';
  }
  template <class Array>
  void nodes(const std::string& name, const Array& values) {
    const long width = values.size() / n_nodes_;
    EXPECT_EQ(width * n_nodes_, values.size())
        << name << ": " << values.size() << " values for " << n_nodes_ << " nodes";
    out_ << "nodes " << name << ' ' << width << '\n';
  }
  void elements(const std::string& name, const std::vector<double>& values, int n) {
    const std::size_t width = n > 0 ? values.size() / static_cast<std::size_t>(n) : 0;
    EXPECT_EQ(width * static_cast<std::size_t>(n), values.size())
        << name << ": " << values.size() << " values for " << n << " elements";
    out_ << "elements " << name << ' ' << width << '\n';
  }
  std::string text() const { return out_.str(); }

 private:
  template <class T>
  static const char* type_name() {
    if constexpr (std::is_same_v<T, double>) {
      return "double";
    } else if constexpr (std::is_same_v<T, long>) {
      return "long";
    } else if constexpr (std::is_same_v<T, int>) {
      return "int";
    } else {
      static_assert(std::is_same_v<T, bool>, "a checkpoint scalar is double, long, int or bool");
      return "bool";
    }
  }
  long n_nodes_;
  std::ostringstream out_;
};

std::string layout_of(const std::string& case_folder) {
  const Model model =
      build_model(read_case(fs::path(SF_SOURCE_DIR) / "cases" / case_folder / "case.toml"));
  const SolutionState state = make_initial_state(model);
  LayoutRecorder recorder(state.x.cols());
  visit_checkpoint_fields(recorder, state);
  return "# cases/" + case_folder + "\n" + recorder.text();
}

TEST(CheckpointLayout, FormatTwoIsTheLayoutOnRecord) {
  // verify_bounce: one tool, one contact, isotropic. The kinematic U-channel: back stresses
  // (Armstrong-Frederick), a force-controlled holder, friction, three tools and contacts.
  const std::string actual =
      layout_of("verify_bounce") + layout_of("u_channel_bhf_2450N_kinematic");
  const fs::path record = fs::path(SF_TEST_DATA_DIR) / "checkpoint_layout_v5.txt";
  if (const char* write = std::getenv("SF_WRITE_CHECKPOINT_LAYOUT"); write && *write == '1') {
    std::ofstream(record) << actual;
  }
  std::ifstream in(record);
  ASSERT_TRUE(in) << "cannot read " << record;
  const std::string expected{std::istreambuf_iterator<char>(in), {}};
  std::istringstream a(actual), e(expected);
  std::string a_line, e_line;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, a_line));
    const bool more_e = static_cast<bool>(std::getline(e, e_line));
    if (!more_a && !more_e) {
      break;
    }
    ASSERT_EQ(more_a ? a_line : "(end)", more_e ? e_line : "(end)")
        << "line " << line << " of " << record
        << ": the checkpoint's layout changed; a change is a new format version";
  }
}

}  // namespace
}  // namespace sf
