// ResultsWriter, the HDF5 wrapper and the XDMF files: write two parts over three frames, read
// everything back bitwise, simulate a killed run, check errors, and (when installed) let
// ParaView 5.11 read the .xdmf files.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "results/hdf5_file.hpp"
#include "results/results_writer.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

using CellMatrix = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic>;
using Tensor6X = Eigen::Matrix<double, 6, Eigen::Dynamic>;

const std::vector<std::string> history_columns = {"time", "kinetic_energy", "punch_force"};

/// A fresh, empty folder for one test's output.
fs::path output_dir(const std::string& name) {
  const fs::path dir = fs::path(SF_BINARY_DIR) / "test-output" / "io_results_writer" / name;
  fs::remove_all(dir);
  return dir;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Awkward doubles, so that a lossy conversion (float, text) anywhere would show up bitwise.
double awkward(int i) {
  switch (i % 5) {
    case 0:
      return -0.0;
    case 1:
      return 1.0 / 3.0 + i;
    case 2:
      return 4.9e-320 * i;  // subnormal
    case 3:
      return -std::nextafter(1e300, 0.0) / i;
    default:
      return std::sqrt(2.0) * i;
  }
}

template <typename Matrix>
Matrix filled(Eigen::Index rows, Eigen::Index cols, int seed) {
  Matrix m(rows, cols);
  for (Eigen::Index i = 0; i < m.size(); ++i) {
    m.data()[i] = awkward(seed + static_cast<int>(i));
  }
  return m;
}

/// True when both hold the same bits (so -0.0 differs from 0.0).
::testing::AssertionResult bitwise_equal(const std::vector<double>& actual, const double* expected,
                                         std::size_t count) {
  if (actual.size() != count) {
    return ::testing::AssertionFailure() << actual.size() << " values, expected " << count;
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (std::bit_cast<std::uint64_t>(actual[i]) != std::bit_cast<std::uint64_t>(expected[i])) {
      return ::testing::AssertionFailure()
             << "value " << i << " is " << actual[i] << ", expected " << expected[i];
    }
  }
  return ::testing::AssertionSuccess();
}

/// A 2-quad blank (6 nodes) and a 1-triangle tool (3 nodes).
std::vector<PartTopology> make_parts() {
  PartTopology blank;
  blank.name = "blank";
  blank.nodes_per_cell = 4;
  blank.cells = CellMatrix(4, 2);
  blank.cells << 0, 1, 1, 2, 4, 5, 3, 4;  // columns: (0 1 4 3), (1 2 5 4)
  blank.reference_nodes = Matrix3X(3, 6);
  blank.reference_nodes << 0, 1, 2, 0, 1, 2,  //
      0, 0, 0, 1, 1, 1,                       //
      0, 0, 0, 0, 0, 0;
  PartTopology tool;
  tool.name = "punch";
  tool.nodes_per_cell = 3;
  tool.cells = CellMatrix(3, 1);
  tool.cells << 0, 1, 2;
  tool.reference_nodes = Matrix3X(3, 3);
  tool.reference_nodes << 0, 1, 0,  //
      0, 0, 1,                      //
      1, 1, 1;
  return {blank, tool};
}

/// Everything written at one frame.
struct FrameData {
  double time = 0.0;
  int cycle = 0;
  Matrix3X blank_x, punch_x, displacement, velocity, contact_force, punch_force;
  Eigen::VectorXd thickness, plastic_strain;
  Tensor6X stress_mid, stress_top, stress_bottom;

  std::vector<PartFrameView> views() const {
    return {
        PartFrameView{
            "punch", punch_x, {{"contact_force", FieldCenter::node, 3, punch_force.data()}}},
        PartFrameView{"blank",
                      blank_x,
                      {{"displacement", FieldCenter::node, 3, displacement.data()},
                       {"velocity", FieldCenter::node, 3, velocity.data()},
                       {"contact_force", FieldCenter::node, 3, contact_force.data()},
                       {"thickness", FieldCenter::cell, 1, thickness.data()},
                       {"plastic_strain", FieldCenter::cell, 1, plastic_strain.data()},
                       {"stress_mid", FieldCenter::cell, 6, stress_mid.data()},
                       {"stress_top", FieldCenter::cell, 6, stress_top.data()},
                       {"stress_bottom", FieldCenter::cell, 6, stress_bottom.data()}}},
    };
  }
};

FrameData make_frame(int k) {
  FrameData f;
  f.time = 1e-3 * (k + 1) / 3.0;  // not exactly representable in decimal
  f.cycle = 1000 * k + 7;
  const int s = 100 * k;
  f.blank_x = filled<Matrix3X>(3, 6, s + 1);
  f.blank_x.row(0).array() += 10.0 * k;  // a distinct, finite first point per frame
  f.blank_x(0, 0) = 0.25 * k;
  f.blank_x(1, 0) = -0.5 * k;
  f.blank_x(2, 0) = 1.0 / 3.0 + k;
  f.punch_x = filled<Matrix3X>(3, 3, s + 2);
  f.punch_x(0, 0) = 2.0 + k;
  f.punch_x(1, 0) = 0.0;
  f.punch_x(2, 0) = 1.0 - 0.125 * k;
  f.displacement = filled<Matrix3X>(3, 6, s + 3);
  f.velocity = filled<Matrix3X>(3, 6, s + 4);
  f.contact_force = filled<Matrix3X>(3, 6, s + 5);
  f.punch_force = filled<Matrix3X>(3, 3, s + 6);
  f.thickness = filled<Eigen::VectorXd>(2, 1, s + 7);
  f.plastic_strain = filled<Eigen::VectorXd>(2, 1, s + 8);
  f.stress_mid = filled<Tensor6X>(6, 2, s + 9);
  f.stress_top = filled<Tensor6X>(6, 2, s + 10);
  f.stress_bottom = filled<Tensor6X>(6, 2, s + 11);
  return f;
}

std::vector<double> history_row(int r) {
  return {1e-4 * r / 3.0, awkward(r + 1), awkward(r + 3)};
}

/// Writes 3 frames, 2 history rows before each, and run information.
void write_three_frames(const fs::path& dir) {
  ResultsWriter writer(dir, make_parts(), history_columns);
  writer.write_run_info("version", "sheetform 0.1.0");
  for (int k = 0; k < 3; ++k) {
    writer.append_history(history_row(2 * k));
    writer.append_history(history_row(2 * k + 1));
    const FrameData frame = make_frame(k);
    writer.write_frame(frame.time, frame.cycle, frame.views());
    EXPECT_EQ(writer.frame_count(), k + 1);
    EXPECT_EQ(writer.history_rows_written(), static_cast<std::size_t>(2 * k + 2));
  }
}

/// The [rows][columns] shape and bitwise content of a dataset.
void expect_dataset(const h5::File& file, const std::string& path, const double* expected,
                    hsize_t rows, hsize_t columns) {
  SCOPED_TRACE(path);
  EXPECT_EQ(file.shape(path), (std::vector<hsize_t>{rows, columns}));
  EXPECT_TRUE(bitwise_equal(file.read_doubles(path), expected, rows * columns));
}

/// Checks a frame group written from make_frame(k).
void expect_frame(const h5::File& file, int k) {
  const FrameData f = make_frame(k);
  const std::string blank = "/parts/blank/frames/" + frame_group_name(k);
  const std::string punch = "/parts/punch/frames/" + frame_group_name(k);
  for (const std::string& group : {blank, punch}) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(file.read_attribute_double(group, "time")),
              std::bit_cast<std::uint64_t>(f.time));
    EXPECT_EQ(file.read_attribute_int(group, "cycle"), f.cycle);
  }
  EXPECT_EQ(file.list(blank),
            (std::vector<std::string>{"contact_force", "coordinates", "displacement",
                                      "plastic_strain", "stress_bottom", "stress_mid", "stress_top",
                                      "thickness", "velocity"}));
  EXPECT_EQ(file.list(punch), (std::vector<std::string>{"contact_force", "coordinates"}));
  expect_dataset(file, blank + "/coordinates", f.blank_x.data(), 6, 3);
  expect_dataset(file, blank + "/displacement", f.displacement.data(), 6, 3);
  expect_dataset(file, blank + "/velocity", f.velocity.data(), 6, 3);
  expect_dataset(file, blank + "/contact_force", f.contact_force.data(), 6, 3);
  expect_dataset(file, blank + "/thickness", f.thickness.data(), 2, 1);
  expect_dataset(file, blank + "/plastic_strain", f.plastic_strain.data(), 2, 1);
  expect_dataset(file, blank + "/stress_mid", f.stress_mid.data(), 2, 6);
  expect_dataset(file, blank + "/stress_top", f.stress_top.data(), 2, 6);
  expect_dataset(file, blank + "/stress_bottom", f.stress_bottom.data(), 2, 6);
  expect_dataset(file, punch + "/coordinates", f.punch_x.data(), 3, 3);
  expect_dataset(file, punch + "/contact_force", f.punch_force.data(), 3, 3);
}

/// The history holds exactly rows 0..rows-1 of history_row().
void expect_history(const h5::File& file, int rows) {
  EXPECT_EQ(file.read_attribute_string("/history", "columns"), "time,kinetic_energy,punch_force");
  for (std::size_t c = 0; c < history_columns.size(); ++c) {
    std::vector<double> expected;
    for (int r = 0; r < rows; ++r) {
      expected.push_back(history_row(r)[c]);
    }
    const std::string path = "/history/" + history_columns[c];
    SCOPED_TRACE(path);
    EXPECT_EQ(file.shape(path), (std::vector<hsize_t>{static_cast<hsize_t>(rows)}));
    EXPECT_TRUE(bitwise_equal(file.read_doubles(path), expected.data(), expected.size()));
  }
}

/// What the <Grid GridType="Uniform"> elements of an .xdmf say.
struct XdmfSummary {
  std::vector<double> times;
  std::vector<std::string> topology_types;
  std::vector<std::string> attributes;  ///< "name Center AttributeType" of every frame
};

XdmfSummary summarize_xdmf(const std::string& text) {
  XdmfSummary summary;
  const std::regex time(R"re(<Time Value="([^"]+)"/>)re");
  const std::regex topology(R"re(TopologyType="([A-Za-z]+)")re");
  const std::regex attribute(
      R"re(<Attribute Name="([^"]+)" Center="(\w+)" AttributeType="(\w+)")re");
  for (std::sregex_iterator i(text.begin(), text.end(), time), end; i != end; ++i) {
    summary.times.push_back(std::strtod((*i)[1].str().c_str(), nullptr));
  }
  for (std::sregex_iterator i(text.begin(), text.end(), topology), end; i != end; ++i) {
    summary.topology_types.push_back((*i)[1]);
  }
  for (std::sregex_iterator i(text.begin(), text.end(), attribute), end; i != end; ++i) {
    summary.attributes.push_back((*i)[1].str() + " " + (*i)[2].str() + " " + (*i)[3].str());
  }
  return summary;
}

std::vector<std::string> repeat(const std::vector<std::string>& items, int times) {
  std::vector<std::string> out;
  for (int i = 0; i < times; ++i) {
    out.insert(out.end(), items.begin(), items.end());
  }
  return out;
}

const std::vector<std::string> blank_attributes = {
    "displacement Node Vector", "velocity Node Vector",       "contact_force Node Vector",
    "thickness Cell Scalar",    "plastic_strain Cell Scalar", "stress_mid Cell Tensor6",
    "stress_top Cell Tensor6",  "stress_bottom Cell Tensor6"};

TEST(ResultsWriter, ReadsBackEveryDatasetBitwise) {
  const fs::path dir = output_dir("read_back");
  write_three_frames(dir);

  h5::File file(dir / "results.h5", h5::FileMode::read_only);
  EXPECT_EQ(file.read_attribute_string("/", "format"), "sheetform results");
  EXPECT_EQ(file.read_attribute_int("/", "format_version"), 1);
  EXPECT_EQ(file.list("/"), (std::vector<std::string>{"history", "parts", "run"}));
  EXPECT_EQ(file.list("/parts"), (std::vector<std::string>{"blank", "punch"}));

  const std::vector<PartTopology> parts = make_parts();
  for (const PartTopology& part : parts) {
    const std::string path = "/parts/" + part.name;
    SCOPED_TRACE(path);
    EXPECT_EQ(file.read_attribute_int(path, "nodes_per_cell"), part.nodes_per_cell);
    EXPECT_EQ(file.shape(path + "/connectivity"),
              (std::vector<hsize_t>{static_cast<hsize_t>(part.cells.cols()),
                                    static_cast<hsize_t>(part.nodes_per_cell)}));
    EXPECT_EQ(file.read_ints(path + "/connectivity"),
              std::vector<int>(part.cells.data(), part.cells.data() + part.cells.size()));
    expect_dataset(file, path + "/reference_coordinates", part.reference_nodes.data(),
                   static_cast<hsize_t>(part.reference_nodes.cols()), 3);
    EXPECT_EQ(file.list(path + "/frames"),
              (std::vector<std::string>{"000000", "000001", "000002"}));
  }
  // Connectivity in file order: cell after cell.
  EXPECT_EQ(file.read_ints("/parts/blank/connectivity"),
            (std::vector<int>{0, 1, 4, 3, 1, 2, 5, 4}));
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    expect_frame(file, k);
  }
  expect_history(file, 6);
  EXPECT_EQ(file.read_string("/run/version"), "sheetform 0.1.0");
  EXPECT_EQ(file.read_attribute_int("/parts", "frames"), 3);  // the commit record
}

TEST(ResultsWriter, XdmfListsEveryFrameWithTimesTopologyAndAttributes) {
  const fs::path dir = output_dir("xdmf");
  write_three_frames(dir);
  const std::vector<double> times = {make_frame(0).time, make_frame(1).time, make_frame(2).time};

  const std::string blank_text = read_text(dir / "blank.xdmf");
  const XdmfSummary blank = summarize_xdmf(blank_text);
  EXPECT_NE(blank_text.find(R"(<Xdmf Version="3.0">)"), std::string::npos);
  EXPECT_NE(blank_text.find(R"(GridType="Collection" CollectionType="Temporal")"),
            std::string::npos);
  EXPECT_EQ(blank.times, times);  // exact: times are written with round-trip precision
  EXPECT_EQ(blank.topology_types, repeat({"Quadrilateral"}, 3));
  EXPECT_EQ(blank.attributes, repeat(blank_attributes, 3));
  EXPECT_NE(blank_text.find(">results.h5:/parts/blank/frames/000002/coordinates</DataItem>"),
            std::string::npos);
  EXPECT_NE(blank_text.find(R"(<DataItem Dimensions="2 4" NumberType="Int" Precision="4" )"
                            R"(Format="HDF">results.h5:/parts/blank/connectivity</DataItem>)"),
            std::string::npos);
  EXPECT_NE(blank_text.find(R"(<DataItem Dimensions="2 6" NumberType="Float" Precision="8" )"
                            R"(Format="HDF">results.h5:/parts/blank/frames/000001/stress_mid<)"),
            std::string::npos);

  const XdmfSummary punch = summarize_xdmf(read_text(dir / "punch.xdmf"));
  EXPECT_EQ(punch.times, times);
  EXPECT_EQ(punch.topology_types, repeat({"Triangle"}, 3));
  EXPECT_EQ(punch.attributes, repeat({"contact_force Node Vector"}, 3));
  EXPECT_FALSE(fs::exists(dir / "blank.xdmf.tmp"));
}

TEST(ResultsWriter, NewWriterStartsWithNoFrames) {
  const fs::path dir = output_dir("fresh");
  write_three_frames(dir);
  ResultsWriter writer(dir, make_parts(), history_columns);  // truncates the previous run
  EXPECT_EQ(writer.frame_count(), 0);
  EXPECT_TRUE(summarize_xdmf(read_text(dir / "blank.xdmf")).times.empty());
  h5::File file(dir / "results.h5", h5::FileMode::read_only);
  EXPECT_TRUE(file.list("/parts/blank/frames").empty());
  EXPECT_EQ(file.shape("/history/time"), (std::vector<hsize_t>{0}));
}

/// Writes 2 frames (history flushed with each), buffers one more history row, then dies by
/// SIGKILL: no destructor, no flush.
[[noreturn]] void write_two_frames_then_die(const fs::path& dir) {
  ResultsWriter writer(dir, make_parts(), history_columns);
  for (int k = 0; k < 2; ++k) {
    writer.append_history(history_row(2 * k));
    writer.append_history(history_row(2 * k + 1));
    const FrameData frame = make_frame(k);
    writer.write_frame(frame.time, frame.cycle, frame.views());
  }
  writer.append_history(history_row(4));
  kill(getpid(), SIGKILL);
  std::abort();
}

TEST(ResultsWriter, KilledRunLeavesTwoConsistentFrames) {
  const fs::path dir = output_dir("killed");
  EXPECT_EXIT(write_two_frames_then_die(dir), ::testing::KilledBySignal(SIGKILL), "");

  h5::File file(dir / "results.h5", h5::FileMode::read_only);
  for (const std::string part : {"blank", "punch"}) {
    EXPECT_EQ(file.list("/parts/" + part + "/frames"),
              (std::vector<std::string>{"000000", "000001"}));
  }
  expect_frame(file, 0);
  expect_frame(file, 1);
  expect_history(file, 4);  // the row buffered after frame 2 is lost, the others are there
  const XdmfSummary blank = summarize_xdmf(read_text(dir / "blank.xdmf"));
  EXPECT_EQ(blank.times, (std::vector<double>{make_frame(0).time, make_frame(1).time}));
  EXPECT_EQ(blank.attributes, repeat(blank_attributes, 2));
  EXPECT_EQ(summarize_xdmf(read_text(dir / "punch.xdmf")).times.size(), 2u);
}

// A frame group past the commit record (a write cut by a kill of every process at once) is not
// a frame: the .xdmf files do not list it, and the next frame's write replaces it.
TEST(ResultsWriter, FrameGroupPastTheCommitRecordIsNotAFrame) {
  const fs::path dir = output_dir("uncommitted");
  ResultsWriter writer(dir, make_parts(), history_columns);
  for (int k = 0; k < 2; ++k) {
    const FrameData frame = make_frame(k);
    writer.write_frame(frame.time, frame.cycle, frame.views());
  }
  {
    h5::File file(dir / "results.h5", h5::FileMode::read_write);
    const std::vector<double> half_written(5, 7.0);
    file.write("/parts/blank/frames/000002/coordinates", half_written, {5});
    file.close();
  }
  {
    h5::File file(dir / "results.h5", h5::FileMode::read_only);
    EXPECT_EQ(file.read_attribute_int("/parts", "frames"), 2);
  }
  EXPECT_EQ(summarize_xdmf(read_text(dir / "blank.xdmf")).times.size(), 2u);
  const FrameData frame = make_frame(2);
  writer.write_frame(frame.time, frame.cycle, frame.views());
  h5::File file(dir / "results.h5", h5::FileMode::read_only);
  EXPECT_EQ(file.read_attribute_int("/parts", "frames"), 3);
  expect_frame(file, 2);
  EXPECT_EQ(summarize_xdmf(read_text(dir / "punch.xdmf")).times.size(), 3u);
}

TEST(ResultsWriter, DestructorAndFlushWriteBufferedHistory) {
  const fs::path dir = output_dir("history");
  {
    ResultsWriter writer(dir, make_parts(), history_columns);
    writer.append_history(history_row(0));
    writer.flush_history();
    EXPECT_EQ(writer.history_rows_written(), 1u);
    writer.append_history(history_row(1));
    writer.append_history(history_row(2));
  }
  h5::File file(dir / "results.h5", h5::FileMode::read_only);
  expect_history(file, 3);
}

TEST(ResultsWriter, RunInfoIsReplacedAndMayExceedAttributeLimits) {
  const fs::path dir = output_dir("run_info");
  const std::string big(200000, 'x');  // larger than an attribute may hold (64 KiB)
  {
    ResultsWriter writer(dir, make_parts(), history_columns);
    writer.write_run_info("case", "first");
    writer.write_run_info("case", big + "\n# ünïcode");
    writer.write_run_info("empty", "");
  }
  h5::File file(dir / "results.h5", h5::FileMode::read_only);
  EXPECT_EQ(file.read_string("/run/case"), big + "\n# ünïcode");
  EXPECT_EQ(file.read_string("/run/empty"), "");
}

/// Runs `statement`, expecting an exception of type E whose message contains every `parts`.
template <typename E, typename F>
void expect_error(F&& statement, const std::vector<std::string>& parts) {
  try {
    statement();
    ADD_FAILURE() << "no exception thrown";
  } catch (const E& e) {
    for (const std::string& part : parts) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "message '" << e.what() << "' does not contain '" << part << "'";
    }
  }
}

TEST(ResultsWriter, UnwritableDirectoryNamesThePath) {
  const fs::path dir = output_dir("unwritable");
  fs::create_directories(dir);
  std::ofstream(dir / "a_file") << "not a directory\n";
  const fs::path below_file = dir / "a_file" / "results";
  expect_error<InputError>([&] { ResultsWriter(below_file, make_parts(), history_columns); },
                           {below_file.string(), "cannot create results directory"});

  // results.h5 exists as a directory: HDF5 cannot create the file.
  fs::create_directories(dir / "blocked" / "results.h5");
  expect_error<InputError>([&] { ResultsWriter(dir / "blocked", make_parts(), history_columns); },
                           {(dir / "blocked" / "results.h5").string(), "cannot create HDF5 file"});

  if (geteuid() != 0) {  // root ignores permissions
    fs::create_directories(dir / "read_only");
    fs::permissions(dir / "read_only", fs::perms::owner_read | fs::perms::owner_exec);
    expect_error<InputError>(
        [&] { ResultsWriter(dir / "read_only", make_parts(), history_columns); },
        {(dir / "read_only").string()});
    fs::permissions(dir / "read_only", fs::perms::owner_all);
  }
}

TEST(ResultsWriter, InvalidArgumentsAreRejectedBeforeWriting) {
  const fs::path dir = output_dir("invalid");
  {
    std::vector<PartTopology> parts = make_parts();
    parts[1].name = "bad/name";
    expect_error<std::invalid_argument>([&] { ResultsWriter(dir, parts, history_columns); },
                                        {"bad/name"});
    parts = make_parts();
    parts[0].cells(2, 1) = 6;
    expect_error<std::invalid_argument>([&] { ResultsWriter(dir, parts, history_columns); },
                                        {"blank", "outside 0..5"});
    expect_error<std::invalid_argument>(
        [&] {
          ResultsWriter(dir, make_parts(), {"time", "time"});
        },
        {"time", "twice"});
  }
  ResultsWriter writer(dir, make_parts(), history_columns);
  const FrameData f0 = make_frame(0);
  writer.write_frame(f0.time, f0.cycle, f0.views());

  const FrameData f1 = make_frame(1);
  expect_error<std::invalid_argument>([&] { writer.write_frame(f0.time, f1.cycle, f1.views()); },
                                      {"time", "greater"});
  std::vector<PartFrameView> views = f1.views();
  expect_error<std::invalid_argument>([&] { writer.write_frame(f1.time, f1.cycle, {views[0]}); },
                                      {"expected every one of the 2 parts"});
  views[0].part = "die";
  expect_error<std::invalid_argument>([&] { writer.write_frame(f1.time, f1.cycle, views); },
                                      {"unknown part 'die'"});
  views = f1.views();
  views[1].fields[3].components = 2;
  expect_error<std::invalid_argument>([&] { writer.write_frame(f1.time, f1.cycle, views); },
                                      {"thickness", "2 components"});
  views = f1.views();
  views[1].fields[4].name = "displacement";
  expect_error<std::invalid_argument>([&] { writer.write_frame(f1.time, f1.cycle, views); },
                                      {"displacement", "twice"});
  const Matrix3X too_few = Matrix3X::Zero(3, 5);
  std::vector<PartFrameView> short_views = {f1.views()[0], PartFrameView{"blank", too_few, {}}};
  expect_error<std::invalid_argument>([&] { writer.write_frame(f1.time, f1.cycle, short_views); },
                                      {"5 node coordinates"});
  expect_error<std::invalid_argument>(
      [&] {
        writer.append_history(std::vector<double>{1.0, 2.0});
      },
      {"expected 3"});

  EXPECT_EQ(writer.frame_count(), 1);
  h5::File file(dir / "results.h5", h5::FileMode::read_only);
  EXPECT_EQ(file.list("/parts/blank/frames"), (std::vector<std::string>{"000000"}));
  EXPECT_EQ(summarize_xdmf(read_text(dir / "blank.xdmf")).times.size(), 1u);
}

TEST(Hdf5File, ErrorsNameTheFileAndTheObject) {
  const fs::path dir = output_dir("hdf5_errors");
  fs::create_directories(dir);
  expect_error<h5::Error>([&] { h5::File(dir / "missing.h5", h5::FileMode::read_only); },
                          {(dir / "missing.h5").string(), "cannot open HDF5 file"});
  h5::File file(dir / "a.h5", h5::FileMode::truncate);
  file.write("/a/b", std::vector<double>{1, 2, 3}, {3});
  expect_error<h5::Error>([&] { file.read_doubles("/a/missing"); },
                          {"/a/missing", (dir / "a.h5").string()});
  expect_error<h5::Error>([&] { file.write("/a/b", std::vector<double>{1}, {1}); },
                          {"cannot create dataset '/a/b'"});
  expect_error<h5::Error>(
      [&] {
        file.write("/c", std::vector<double>{1, 2}, {3});
      },
      {"shape [3] does not hold 2 values"});
  EXPECT_TRUE(file.exists("/a/b"));
  EXPECT_FALSE(file.exists("/x/y"));
  file.create_extendible("/e", 2);
  file.append("/e", std::vector<double>{1, 2, 3});
  file.append("/e", std::vector<double>{4});
  EXPECT_EQ(file.read_doubles("/e"), (std::vector<double>{1, 2, 3, 4}));
  file.close();
  expect_error<h5::Error>([&] { file.read_doubles("/e"); }, {"is closed"});
}

/// Runs check_xdmf.py on one part; returns its exit code and appends its output to `log`.
int run_check_xdmf(const fs::path& xdmf, const std::string& arguments, std::string& log) {
  const fs::path output = xdmf.parent_path() / (xdmf.stem().string() + "_check.log");
  // From '/', so that relative DataItem paths must resolve against the .xdmf's folder.
  const std::string command =
      "cd / && /usr/bin/pvpython '" SF_SOURCE_DIR "/scripts/check_xdmf.py' '" + xdmf.string() +
      "' " + arguments + " > '" + output.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  log += "$ " + command + "\n" + read_text(output);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string times_argument(int frames) {
  std::string text = "--times";
  for (int k = 0; k < frames; ++k) {
    char buffer[40];
    std::snprintf(buffer, sizeof(buffer), " %.17g", make_frame(k).time);
    text += buffer;
  }
  return text;
}

std::string first_points_argument(int frames, bool blank) {
  std::string text = "--first-points";
  for (int k = 0; k < frames; ++k) {
    const FrameData f = make_frame(k);
    const Matrix3X& x = blank ? f.blank_x : f.punch_x;
    for (int i = 0; i < 3; ++i) {
      char buffer[40];
      std::snprintf(buffer, sizeof(buffer), " %.17g", x(i, 0));
      text += buffer;
    }
  }
  return text;
}

const std::string blank_arrays =
    " --point-arrays displacement:3 velocity:3 contact_force:3"
    " --cell-arrays thickness:1 plastic_strain:1 stress_mid:6 stress_top:6 stress_bottom:6";

TEST(ResultsWriter, ParaViewReadsTheXdmfFiles) {
  if (!fs::exists("/usr/bin/pvpython")) {
    GTEST_SKIP() << "ParaView is not installed (/usr/bin/pvpython missing); CI installs it";
  }
  const fs::path dir = output_dir("paraview");
  write_three_frames(dir);
  std::string log;
  EXPECT_EQ(run_check_xdmf(dir / "blank.xdmf",
                           times_argument(3) + " --points 6 --cells 2" + blank_arrays + " " +
                               first_points_argument(3, true),
                           log),
            0)
      << log;
  EXPECT_EQ(run_check_xdmf(dir / "punch.xdmf",
                           times_argument(3) + " --points 3 --cells 1" +
                               " --point-arrays contact_force:3 " + first_points_argument(3, false),
                           log),
            0)
      << log;
  // The check can fail: a wrong expectation gives a non-zero exit code.
  EXPECT_NE(run_check_xdmf(
                dir / "punch.xdmf",
                times_argument(2) + " --points 3 --cells 1 --point-arrays contact_force:3", log),
            0)
      << log;

  // A killed run is readable too, with its 2 frames.
  const fs::path killed = output_dir("paraview_killed");
  EXPECT_EXIT(write_two_frames_then_die(killed), ::testing::KilledBySignal(SIGKILL), "");
  EXPECT_EQ(run_check_xdmf(killed / "blank.xdmf",
                           times_argument(2) + " --points 6 --cells 2" + blank_arrays + " " +
                               first_points_argument(2, true),
                           log),
            0)
      << log;
}

TEST(ResultsWriter, MixedPartHasOneMixedTopologyThatParaViewReads) {
  // A blank of 1 quad and 2 triangles (a mixed shell part, cells numbered quads first): the
  // HDF5 file keeps the quads in connectivity and the triangles in triangle_connectivity,
  // nodes_per_cell = 0 marks the mix, and the .xdmf points to mixed_connectivity, the XDMF 3
  // "Mixed" array (type code 5 Quadrilateral or 4 Triangle, then the nodes, per cell). ParaView
  // must read 5 points and 3 cells with a 3-cell field (when installed).
  const fs::path dir = output_dir("mixed");
  PartTopology blank;
  blank.name = "blank";
  blank.nodes_per_cell = 4;
  blank.cells = CellMatrix(4, 1);
  blank.cells << 0, 1, 3, 2;
  blank.triangles = TriConn(3, 2);
  blank.triangles.col(0) << 1, 4, 3;
  blank.triangles.col(1) << 3, 4, 2;
  blank.reference_nodes = Matrix3X(3, 5);
  blank.reference_nodes << 0, 1, 0, 1, 2,  //
      0, 0, 1, 1, 0.5,                     //
      0, 0, 0, 0, 0;
  const Eigen::VectorXd thickness = Eigen::Vector3d(1.0, 0.9, 0.8);
  {
    ResultsWriter writer(dir, {blank}, {"time"});
    writer.write_frame(0.5, 3,
                       {PartFrameView{"blank",
                                      blank.reference_nodes,
                                      {{"thickness", FieldCenter::cell, 1, thickness.data()}}}});
  }
  h5::File file(dir / "results.h5", h5::FileMode::read_only);
  EXPECT_EQ(file.read_attribute_int("/parts/blank", "nodes_per_cell"), 0);
  EXPECT_EQ(file.read_ints("/parts/blank/connectivity"), (std::vector<int>{0, 1, 3, 2}));
  EXPECT_EQ(file.read_ints("/parts/blank/triangle_connectivity"),
            (std::vector<int>{1, 4, 3, 3, 4, 2}));
  EXPECT_EQ(file.read_ints("/parts/blank/mixed_connectivity"),
            (std::vector<int>{5, 0, 1, 3, 2, 4, 1, 4, 3, 4, 3, 4, 2}));
  file.close();
  const std::string text = read_text(dir / "blank.xdmf");
  EXPECT_NE(text.find(R"(<Topology TopologyType="Mixed" NumberOfElements="3">)"), std::string::npos)
      << text;
  EXPECT_NE(text.find(R"(<DataItem Dimensions="13" NumberType="Int" Precision="4" )"
                      R"(Format="HDF">results.h5:/parts/blank/mixed_connectivity</DataItem>)"),
            std::string::npos)
      << text;
  if (!fs::exists("/usr/bin/pvpython")) {
    GTEST_SKIP() << "ParaView is not installed (/usr/bin/pvpython missing); CI installs it";
  }
  std::string log;
  EXPECT_EQ(run_check_xdmf(dir / "blank.xdmf",
                           "--times 0.5 --points 5 --cells 3 --cell-arrays thickness:1", log),
            0)
      << log;
  // The check can fail: a wrong cell count gives a non-zero exit code.
  EXPECT_NE(run_check_xdmf(dir / "blank.xdmf",
                           "--times 0.5 --points 5 --cells 2 --cell-arrays thickness:1", log),
            0)
      << log;
}

}  // namespace
}  // namespace sf
