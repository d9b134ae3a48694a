// A .geo that tries to run commands, write files or read outside its folder, through every route
// gmsh's language has, with the .geo scan switched off: the sandbox alone stops each one
// (docs/security.md). Each attack's marker file must not appear, and the run must end in an
// InputError naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "meshing/geo_safety.hpp"
#include "meshing/gmsh_reader.hpp"
#include "meshing/sandbox.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

// A valid blank, so that a .geo fails only by what the attack does.
const char* kPlate = R"(
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("blank") = {1};
)";

/// The scan off for one test: the sandbox must hold alone.
class GmshSandbox : public ::testing::Test {
 protected:
  void SetUp() override {
    geo_scan_enabled() = false;
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    root_ = fs::path(SF_BINARY_DIR) / "test_scratch" / "gmsh_sandbox" / name;
    fs::remove_all(root_);
    fs::create_directories(case_dir());
    fs::create_directories(elsewhere());
  }
  void TearDown() override { geo_scan_enabled() = true; }

  fs::path case_dir() const { return root_ / "case"; }
  fs::path elsewhere() const { return root_ / "elsewhere"; }
  fs::path marker() const { return elsewhere() / "pwned"; }

  void write(const std::string& name, const std::string& text) const {
    std::ofstream(case_dir() / name) << text;
  }
  std::string touch_marker() const { return "SystemCall \"touch " + marker().string() + "\";\n"; }

  /// Meshes case/blank.geo and returns the InputError's message ("" and a failure if none).
  std::string error_of_blank() const {
    try {
      load_gmsh_model(case_dir() / "blank.geo", 0.0, false);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError";
    return {};
  }

  void expect_program_refused(const std::string& message) const {
    EXPECT_NE(message.find("blank.geo"), std::string::npos) << message;
    EXPECT_NE(message.find("tried to start a program"), std::string::npos) << message;
    EXPECT_FALSE(fs::exists(marker()));
  }

  fs::path root_;
};

TEST_F(GmshSandbox, SystemCallInTheFile) {
  write("blank.geo", std::string(kPlate) + touch_marker());
  expect_program_refused(error_of_blank());
}

TEST_F(GmshSandbox, NonBlockingSystemCall) {
  write("blank.geo",
        std::string(kPlate) + "NonBlockingSystemCall \"touch " + marker().string() + "\";\n");
  expect_program_refused(error_of_blank());
}

TEST_F(GmshSandbox, IncludeOfAnotherExtension) {
  write("payload.txt", touch_marker());
  write("blank.geo", std::string(kPlate) + "Include \"payload.txt\";\n");
  expect_program_refused(error_of_blank());
}

TEST_F(GmshSandbox, IncludeOfUpperCaseGeo) {
  write("PAYLOAD.GEO", touch_marker());
  write("blank.geo", std::string(kPlate) + "Include \"PAYLOAD.GEO\";\n");
  expect_program_refused(error_of_blank());
}

TEST_F(GmshSandbox, MergeOfATextFile) {
  write("payload.txt", touch_marker());  // gmsh parses a merged .txt as a script
  write("blank.geo", std::string(kPlate) + "Merge \"payload.txt\";\n");
  expect_program_refused(error_of_blank());
}

TEST_F(GmshSandbox, NestedIncludes) {
  write("inner.inc", touch_marker());
  write("middle.txt", "Include \"inner.inc\";\n");
  write("blank.geo", std::string(kPlate) + "Include \"middle.txt\";\n");
  expect_program_refused(error_of_blank());
}

TEST_F(GmshSandbox, ComputedName) {
  write("payload.txt", touch_marker());
  write("blank.geo", std::string(kPlate) + "Include StrCat(\"pay\", \"load.txt\");\n");
  expect_program_refused(error_of_blank());
}

TEST_F(GmshSandbox, OnelabRun) {
  write("blank.geo",
        std::string(kPlate) + "OnelabRun(\"x\", \"touch " + marker().string() + "\");\n");
  const std::string message = error_of_blank();
  EXPECT_NE(message.find("blank.geo"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(marker()));
}

TEST_F(GmshSandbox, PrintfToAFileOutside) {
  if (sandbox_support().landlock_abi == 0) {
    GTEST_SKIP() << sandbox_support().describe();
  }
  write("blank.geo", std::string(kPlate) + "Printf(\"pwned\") > \"" + marker().string() + "\";\n");
  const std::string message = error_of_blank();
  EXPECT_NE(message.find("blank.geo"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(marker()));
}

TEST_F(GmshSandbox, PrintfToAFileInTheCaseFolder) {
  if (sandbox_support().landlock_abi == 0) {
    GTEST_SKIP() << sandbox_support().describe();
  }
  write("blank.geo", std::string(kPlate) + "Printf(\"pwned\") > \"written.txt\";\n");
  const std::string message = error_of_blank();
  EXPECT_NE(message.find("blank.geo"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(case_dir() / "written.txt"));
}

TEST_F(GmshSandbox, ReadingAFileOutsideTheCaseFolder) {
  if (sandbox_support().landlock_abi == 0) {
    GTEST_SKIP() << sandbox_support().describe();
  }
  // A valid geometry elsewhere: read, it would mesh; its text must not come back either.
  std::ofstream(elsewhere() / "secret.geo") << "// SECRET-7f3a\n" << kPlate;
  write("blank.geo", "Include \"../elsewhere/secret.geo\";\n");
  const std::string message = error_of_blank();
  EXPECT_NE(message.find("blank.geo"), std::string::npos) << message;
  EXPECT_EQ(message.find("SECRET-7f3a"), std::string::npos) << message;
  write("blank.geo", "Merge \"/etc/hostname\";\n");
  EXPECT_NE(error_of_blank().find("blank.geo"), std::string::npos);
}

TEST_F(GmshSandbox, AnEndlessLoopIsStoppedAtTheLimit) {
  write("blank.geo", std::string(kPlate) + "For i In {1:1e15}\nEndFor\n");
  try {
    load_gmsh_model(case_dir() / "blank.geo", 0.0, false, {}, {}, MeshLimits{.seconds = 1.0});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("within 1 s (limits.mesh_seconds"), std::string::npos) << message;
  }
}

TEST_F(GmshSandbox, TheFileItselfStillMeshes) {
  write("blank.geo", kPlate);
  const GmshModel model = load_gmsh_model(case_dir() / "blank.geo", 0.0, false);
  EXPECT_NE(model.find_group("blank", 2), nullptr);
}

TEST_F(GmshSandbox, MeshesAfterThreadsHaveRun) {
  // The child is forked from a process whose OpenMP threads exist (a run's earlier parallel
  // regions): gmsh in the child must not wait on them.
  write("blank.geo", kPlate);
  double sum = 0.0;
#pragma omp parallel for num_threads(2) reduction(+ : sum)
  for (int i = 0; i < 1000; ++i) {
    sum += i;
  }
  ASSERT_EQ(sum, 499500.0);
  const GmshModel model = load_gmsh_model(case_dir() / "blank.geo", 0.0, false);
  EXPECT_NE(model.find_group("blank", 2), nullptr);
}

TEST_F(GmshSandbox, TheScanGivesTheFirstMessage) {
  geo_scan_enabled() = true;
  write("payload.txt", touch_marker());
  write("blank.geo", std::string(kPlate) + "Include \"payload.txt\";\n");
  const std::string message = error_of_blank();
  EXPECT_NE(message.find("payload.txt', line 1: the statement SystemCall"), std::string::npos)
      << message;
  EXPECT_FALSE(fs::exists(marker()));
}

}  // namespace
}  // namespace sf
