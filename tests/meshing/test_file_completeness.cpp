// CAD and STL files that cannot be read completely (meshing/file_completeness.hpp), and the ones
// that crash or hang gmsh and OpenCASCADE (found by mutating tests/data/cad/punch.step): each is an
// InputError naming the file, never a crash of sheetform or a wait for the default limit.
#include "meshing/file_completeness.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "meshing/gmsh_reader.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

const fs::path cad_dir = fs::path(SF_TEST_DATA_DIR) / "cad";

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The InputError's message of checking `bytes` as `name`, "" if none.
std::string check_error(const std::string& name, const std::string& bytes) {
  const fs::path file = name;
  try {
    check_file_is_whole(file, mesh_format(file), bytes);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(SF_BINARY_DIR) / "test_scratch" / "file_completeness" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(FileCompleteness, WholeFilesPass) {
  for (const char* name : {"punch.step", "punch_metres.step", "plate.step", "punch.iges",
                           "punch.brep", "box_binary.stl", "die_open.stl"}) {
    EXPECT_EQ(check_error(name, bytes_of(cad_dir / name)), "") << name;
  }
}

// Every cut of a file, from a few bytes to all but the last one, is found.
void expect_every_cut_found(const char* name, const char* said) {
  const std::string whole = bytes_of(cad_dir / name);
  int cuts = 0;
  for (std::size_t size = 1; size < whole.size(); size += 1 + whole.size() / 97) {
    std::string cut = whole.substr(0, size);
    // A cut that ends in blank space only is not a cut.
    if (cut.find_last_not_of(" \r\n\t") == whole.find_last_not_of(" \r\n\t")) {
      continue;
    }
    const std::string message = check_error(name, cut);
    EXPECT_NE(message.find(name), std::string::npos) << name << " cut at " << size;
    ++cuts;
    if (size > 100) {  // past the header: the message says what is missing
      EXPECT_NE(message.find(said), std::string::npos)
          << name << " cut at " << size << ": " << message;
    }
  }
  EXPECT_GT(cuts, 90) << name;
}

TEST(FileCompleteness, TruncatedStepIsFound) {
  expect_every_cut_found("punch.step", "does not end with END-ISO-10303-21;");
}

TEST(FileCompleteness, TruncatedIgesIsFound) {
  expect_every_cut_found("punch.iges", "not whole");
}

TEST(FileCompleteness, TruncatedBrepIsFound) {
  expect_every_cut_found("punch.brep", "not whole");
}

TEST(FileCompleteness, TruncatedAsciiStlIsFound) {
  expect_every_cut_found("die_open.stl", "not whole");
}

TEST(FileCompleteness, TruncatedBinaryStlIsFound) {
  const std::string whole = bytes_of(cad_dir / "box_binary.stl");
  for (std::size_t size = 0; size < whole.size(); size += 7) {
    const std::string message = check_error("box.stl", whole.substr(0, size));
    EXPECT_NE(message.find("not a whole STL file"), std::string::npos) << size << ": " << message;
  }
}

TEST(FileCompleteness, IgesCountsAreChecked) {
  std::string iges = bytes_of(cad_dir / "punch.iges");
  // Remove one Parameter record (the one before the Start-Global-Directory-Parameter counts).
  const std::size_t terminate = iges.rfind('\n', iges.size() - 2);
  const std::size_t last_p = iges.rfind('\n', terminate - 1);
  iges.erase(last_p, terminate - last_p);
  const std::string message = check_error("punch.iges", iges);
  EXPECT_NE(message.find("counts 48 P records, the file has 47"), std::string::npos) << message;
}

TEST(FileCompleteness, NotTheFormatItsNameSays) {
  EXPECT_NE(check_error("a.step", "hello").find("not a STEP file"), std::string::npos);
  EXPECT_NE(check_error("a.brep", "hello\n").find("not an OpenCASCADE BREP"), std::string::npos);
  EXPECT_NE(check_error("a.iges", "hello\n").find("not an IGES file"), std::string::npos);
  EXPECT_NE(check_error("a.stl", "hello\n").find("not a whole STL file"), std::string::npos);
  // An STL that says solid but holds something else.
  EXPECT_NE(check_error("a.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex a b c\n")
                .find("where a coordinate belongs (line 4)"),
            std::string::npos);
}

TEST(FileCompleteness, ATruncatedFileIsRefusedBeforeGmshReadsIt) {
  const fs::path dir = scratch("refused");
  const std::string brep = bytes_of(cad_dir / "punch.brep");
  std::ofstream(dir / "punch.brep", std::ios::binary) << brep.substr(0, brep.size() / 2);
  const auto start = std::chrono::steady_clock::now();
  try {
    load_gmsh_model(dir / "punch.brep", 5.0, false);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the BREP file is not whole"), std::string::npos)
        << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

TEST(FileCompleteness, AStepThatCrashesOpenCascadeIsAnInputError) {
  // gmsh 4.8 itself (gmsh -2 crashes_opencascade.step) ends with a segmentation fault.
  try {
    load_gmsh_model(cad_dir / "crashes_opencascade.step", 5.0, false);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("crashes_opencascade.step': gmsh crashed reading it"), std::string::npos)
        << message;
  }
}

TEST(FileCompleteness, AStepOnWhichGmshHangsIsStoppedAtTheLimit) {
  // gmsh 4.8 meshes one of its faces without end (gmsh -2 hangs_gmsh_meshing.step: still
  // meshing surface 1 after 120 s).
  const auto start = std::chrono::steady_clock::now();
  try {
    load_gmsh_model(cad_dir / "hangs_gmsh_meshing.step", 5.0, false, {}, {},
                    MeshLimits{.seconds = 2.0});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("within 2 s (limits.mesh_seconds; stopped while meshing)"),
              std::string::npos)
        << message;
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

}  // namespace
}  // namespace sf
