// A part whose mesh changes during a run (a trim, solver/trim.hpp): the frames before the change
// keep the first mesh, the frames after it name the new one (results.h5
// /parts/<name>/topologies/<k>, the frame attribute `topology`), in results.h5 and in the .xdmf
// ParaView reads; a writer taking the results up again (a restart, the run after a trim) keeps
// each frame's mesh, and a restart from before the change drops it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "results/hdf5_file.hpp"
#include "results/results_writer.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;
using CellMatrix = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic>;

fs::path output_dir(const std::string& name) {
  const fs::path dir = fs::path(SF_BINARY_DIR) / "test_output" / "results_topology" / name;
  fs::remove_all(dir);
  return dir;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A strip of `quads` quadrilaterals along x (2 (quads + 1) nodes).
PartTopology strip(int quads) {
  PartTopology p;
  p.name = "blank";
  p.nodes_per_cell = 4;
  p.cells = CellMatrix(4, quads);
  p.reference_nodes = Matrix3X::Zero(3, 2 * (quads + 1));
  for (int i = 0; i <= quads; ++i) {
    p.reference_nodes.col(2 * i) = Vec3(i, 0.0, 0.0);
    p.reference_nodes.col(2 * i + 1) = Vec3(i, 1.0, 0.0);
  }
  for (int e = 0; e < quads; ++e) {
    p.cells.col(e) << 2 * e, 2 * e + 2, 2 * e + 3, 2 * e + 1;
  }
  return p;
}

// Writes a frame of the strip as it stands: coordinates and a cell field of the element count.
void write_strip_frame(ResultsWriter& writer, const PartTopology& p, double time) {
  const Matrix3X x = p.reference_nodes;
  const std::vector<double> cells(static_cast<std::size_t>(p.cells.cols()),
                                  static_cast<double>(p.cells.cols()));
  writer.write_frame(
      time, static_cast<int>(1000 * time),
      {PartFrameView{"blank", x, {{"elements", FieldCenter::cell, 1, cells.data()}}}});
}

// The connectivity dataset each frame's grid names, in order.
std::vector<std::string> frame_connectivities(const std::string& xdmf) {
  std::vector<std::string> out;
  const std::regex item(R"re(results\.h5:(/parts/blank/[a-z0-9/]*connectivity))re");
  for (std::sregex_iterator i(xdmf.begin(), xdmf.end(), item), end; i != end; ++i) {
    out.push_back((*i)[1]);
  }
  return out;
}

const std::vector<std::string> kFirst = {"/parts/blank/connectivity"};
const std::string kSecond = "/parts/blank/topologies/1/connectivity";

TEST(ResultsTopologyChange, FramesAfterAChangeNameTheNewMeshAndTheEarlierOnesKeepTheirs) {
  const fs::path dir = output_dir("change");
  const PartTopology before = strip(3), after = strip(2);
  {
    ResultsWriter writer(dir, {before}, {"time"});
    write_strip_frame(writer, before, 0.0);
    write_strip_frame(writer, before, 1.0);
    writer.change_topology(after);
    write_strip_frame(writer, after, 2.0);
    // A frame of the old mesh is refused now.
    EXPECT_THROW(write_strip_frame(writer, before, 3.0), std::invalid_argument);
  }
  EXPECT_EQ(frame_connectivities(read_text(dir / "blank.xdmf")),
            (std::vector<std::string>{kFirst[0], kFirst[0], kSecond}));
  EXPECT_NE(read_text(dir / "blank.xdmf").find("Dimensions=\"6 3\""), std::string::npos);
  {
    const h5::File file(dir / "results.h5", h5::FileMode::read_only);
    EXPECT_EQ(file.shape("/parts/blank/connectivity"), (std::vector<hsize_t>{3, 4}));
    EXPECT_EQ(file.shape(kSecond), (std::vector<hsize_t>{2, 4}));
    EXPECT_EQ(file.read_attribute_int("/parts/blank/topologies/1", "first_frame"), 2);
    EXPECT_EQ(file.read_attribute_int("/parts/blank/frames/000002", "topology"), 1);
    EXPECT_FALSE(file.has_attribute("/parts/blank/frames/000001", "topology"));
    EXPECT_EQ(file.shape("/parts/blank/frames/000002/elements"), (std::vector<hsize_t>{2, 1}));
  }

  // Taken up with every frame kept (the run after a second trim): each frame keeps its mesh.
  std::string run_id;
  {
    const h5::File file(dir / "results.h5", h5::FileMode::read_only);
    run_id = file.read_attribute_string("/run", "run_id");
  }
  {
    ResultsWriter writer(dir, {after}, {"time"}, ResultsWriter::Resume{3, 0, run_id});
    const PartTopology last = strip(1);
    writer.change_topology(last);
    write_strip_frame(writer, last, 3.0);
  }
  EXPECT_EQ(frame_connectivities(read_text(dir / "blank.xdmf")),
            (std::vector<std::string>{kFirst[0], kFirst[0], kSecond,
                                      "/parts/blank/topologies/2/connectivity"}));

  // A restart from before the first change: the later meshes go with the later frames.
  { ResultsWriter writer(dir, {before}, {"time"}, ResultsWriter::Resume{2, 0, run_id}); }
  EXPECT_EQ(frame_connectivities(read_text(dir / "blank.xdmf")),
            (std::vector<std::string>{kFirst[0], kFirst[0]}));
  const h5::File file(dir / "results.h5", h5::FileMode::read_only);
  EXPECT_TRUE(file.list("/parts/blank/topologies").empty());
}

TEST(ResultsTopologyChange, ABadMeshOrAnUnknownPartIsRefused) {
  const fs::path dir = output_dir("bad");
  ResultsWriter writer(dir, {strip(2)}, {"time"});
  PartTopology unknown = strip(1);
  unknown.name = "punch";
  EXPECT_THROW(writer.change_topology(unknown), std::invalid_argument);
  PartTopology outside = strip(1);
  outside.cells(0, 0) = 9;  // a node the mesh does not have
  EXPECT_THROW(writer.change_topology(outside), std::invalid_argument);
}

}  // namespace
}  // namespace sf
