// The MSH 4.1 binary reader (meshing/msh_file.hpp) against gmsh's own reading of the same model,
// and on damaged files: every cut and a set of wrong counts end in an InputError.
#include "meshing/msh_file.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

const fs::path data_dir = SF_TEST_DATA_DIR;
const fs::path cup_dir = fs::path(SF_SOURCE_DIR) / "cases" / "square_cup_aluminium";

/// A folder of this test's own: ctest runs the tests of this file side by side, and a folder
/// shared between them would be emptied by one while another writes into it.
fs::path scratch(const std::string& name) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const fs::path dir = fs::path(SF_BINARY_DIR) / "test_scratch" / "msh_file" / test / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// What gmsh's API says of the model it holds, in GmshModel's form (the mesh reader's old
/// in-process reading, kept here as the reference).
GmshModel model_from_gmsh_api() {
  GmshModel model;
  std::vector<std::size_t> tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
  for (std::size_t i = 0; i < tags.size(); ++i) {
    model.node_index[tags[i]] = static_cast<int>(i);
  }
  model.node_tags = tags;
  model.node_coords =
      Eigen::Map<Matrix3X>(coords.data(), 3, static_cast<Eigen::Index>(tags.size()));
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  std::sort(groups.begin(), groups.end());
  for (const auto& [dim, tag] : groups) {
    GmshPhysicalGroup g;
    g.dim = dim;
    g.tag = tag;
    gmsh::model::getPhysicalName(dim, tag, g.name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (const int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, entity);
      for (std::size_t k = 0; k < types.size(); ++k) {
        auto same = std::find_if(g.elements.begin(), g.elements.end(),
                                 [&](const GmshElementBlock& b) { return b.type == types[k]; });
        if (same == g.elements.end()) {
          g.elements.push_back({types[k], "", 0, {}, {}});
          same = g.elements.end() - 1;
        }
        same->element_tags.insert(same->element_tags.end(), element_tags[k].begin(),
                                  element_tags[k].end());
        same->node_tags.insert(same->node_tags.end(), node_tags[k].begin(), node_tags[k].end());
      }
    }
    std::vector<double> ignored;
    gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, g.node_tags, ignored);
    std::sort(g.node_tags.begin(), g.node_tags.end());
    model.groups.push_back(g);
  }
  return model;
}

/// Opens (and meshes) `file` in this process's gmsh, writes it as MSH 4.1 binary the way the
/// sandboxed job does, and returns gmsh's view and the written file's bytes.
std::pair<GmshModel, std::string> through_gmsh(const fs::path& file, double size, bool mesh) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.NumThreads", 1);
  if (size > 0) {
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  }
  gmsh::open(file.string());
  if (mesh) {
    gmsh::model::mesh::generate(2);
  }
  gmsh::vectorpair groups, surfaces;
  gmsh::model::getPhysicalGroups(groups);
  if (groups.empty()) {  // a CAD or STL file: its surfaces as one part, as the job makes them
    gmsh::model::getEntities(surfaces, 2);
    std::vector<int> tags;
    for (const auto& [dim, tag] : surfaces) {
      tags.push_back(tag);
    }
    gmsh::model::addPhysicalGroup(2, tags, 1);
    gmsh::model::setPhysicalName(2, 1, "tool");
  }
  const fs::path out = scratch(file.stem().string()) / "mesh.msh";
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::option::setNumber("Mesh.SaveAll", 0);
  gmsh::option::setNumber("Mesh.Binary", 1);
  gmsh::write(out.string());
  GmshModel reference = model_from_gmsh_api();
  gmsh::finalize();
  return {reference, bytes_of(out)};
}

void expect_same_model(const GmshModel& ours, const GmshModel& gmsh_view, const std::string& what) {
  ASSERT_EQ(ours.groups.size(), gmsh_view.groups.size()) << what;
  std::size_t nodes_used = 0;
  for (std::size_t g = 0; g < ours.groups.size(); ++g) {
    const GmshPhysicalGroup &a = ours.groups[g], &b = gmsh_view.groups[g];
    EXPECT_EQ(a.name, b.name) << what;
    EXPECT_EQ(a.dim, b.dim) << what;
    EXPECT_EQ(a.tag, b.tag) << what;
    EXPECT_EQ(a.node_tags, b.node_tags) << what << " group " << a.name;
    ASSERT_EQ(a.elements.size(), b.elements.size()) << what << " group " << a.name;
    for (std::size_t k = 0; k < a.elements.size(); ++k) {
      EXPECT_EQ(a.elements[k].type, b.elements[k].type) << what;
      EXPECT_EQ(a.elements[k].element_tags, b.elements[k].element_tags) << what;
      EXPECT_EQ(a.elements[k].node_tags, b.elements[k].node_tags) << what;
      EXPECT_EQ(a.elements[k].nodes_per_element,
                static_cast<int>(a.elements[k].node_tags.size() /
                                 std::max<std::size_t>(1, a.elements[k].element_tags.size())));
    }
    for (const std::size_t tag : a.node_tags) {  // the same coordinates, bit for bit
      const auto mine = ours.node_index.find(tag), theirs = gmsh_view.node_index.find(tag);
      ASSERT_TRUE(mine != ours.node_index.end() && theirs != gmsh_view.node_index.end());
      for (int d = 0; d < 3; ++d) {
        EXPECT_EQ(ours.node_coords(d, mine->second), gmsh_view.node_coords(d, theirs->second))
            << what << " node " << tag;
      }
      ++nodes_used;
    }
  }
  EXPECT_GT(nodes_used, 0u) << what;
}

TEST(MshFile, ReadsWhatGmshHolds) {
  struct Source {
    fs::path file;
    double size;
    bool mesh;
  };
  for (const Source& s :
       {Source{cup_dir / "blank.geo", 0.0, true}, Source{cup_dir / "punch.geo", 0.0, true},
        Source{data_dir / "cad" / "punch.step", 5.0, true},
        Source{data_dir / "cad" / "die_open.stl", 0.0, false},
        Source{data_dir / "other_codes" / "sheet_groups.unv", 0.0, false}}) {
    const auto [reference, bytes] = through_gmsh(s.file, s.size, s.mesh);
    expect_same_model(parse_msh41_binary(bytes, s.file), reference, s.file.string());
  }
}

TEST(MshFile, EveryCutIsAnInputError) {
  const auto [reference, bytes] = through_gmsh(data_dir / "cad" / "die_open.stl", 0.0, false);
  ASSERT_NO_THROW(parse_msh41_binary(bytes, "die.stl"));
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    try {
      parse_msh41_binary(std::string_view(bytes).substr(0, size), "die.stl");
      // A cut at a section's end is a whole file with fewer sections: without $Elements it is
      // refused, after it the rest ($Periodic) is optional.
      EXPECT_NE(std::string_view(bytes).substr(0, size).find("$EndElements"), std::string::npos)
          << size;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("'die.stl': the mesh gmsh wrote"), std::string::npos);
    }
  }
}

/// The file with the 8 bytes at `offset` replaced by `value`.
std::string with_size_at(std::string bytes, std::size_t offset, std::uint64_t value) {
  if (offset > bytes.size() || bytes.size() - offset < sizeof(value)) {
    ADD_FAILURE() << "offset " << offset << " is not inside the file of " << bytes.size()
                  << " bytes";
    return bytes;
  }
  std::memcpy(bytes.data() + offset, &value, sizeof(value));
  return bytes;
}

std::string error_of(const std::string& bytes) {
  try {
    parse_msh41_binary(bytes, "x.msh");
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(MshFile, CountsLargerThanTheFileAreRefusedBeforeAllocating) {
  const auto [reference, bytes] = through_gmsh(data_dir / "cad" / "die_open.stl", 0.0, false);
  ASSERT_NE(bytes.find("$Nodes\n"), std::string::npos);
  ASSERT_NE(bytes.find("$Elements\n"), std::string::npos);
  const std::size_t nodes = bytes.find("$Nodes\n") + 7, elements = bytes.find("$Elements\n") + 10;
  for (const std::size_t at : {nodes, nodes + 8, elements, elements + 8}) {
    const std::string message = error_of(with_size_at(bytes, at, std::uint64_t(1) << 60));
    EXPECT_NE(message.find("larger than the file"), std::string::npos) << at << ": " << message;
  }
}

TEST(MshFile, RandomDamageIsNeverACrash) {
  const auto [reference, bytes] = through_gmsh(data_dir / "cad" / "die_open.stl", 0.0, false);
  std::mt19937 random(12345);
  int refused = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string damaged = bytes;
    const int flips = 1 + static_cast<int>(random() % 4);
    for (int f = 0; f < flips; ++f) {
      damaged[random() % damaged.size()] = static_cast<char>(random() % 256);
    }
    try {
      const GmshModel model = parse_msh41_binary(damaged, "x.msh");
      for (const auto& g : model.groups) {  // what it returns is consistent
        for (const auto& b : g.elements) {
          for (const std::size_t n : b.node_tags) {
            ASSERT_EQ(model.node_index.count(n), 1u);
          }
        }
      }
    } catch (const InputError&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 100);  // most damage is found; the rest changed a coordinate or a name
}

TEST(MshFile, AnElementNamingANodeThatIsNotThereIsRefused) {
  const auto [reference, bytes] = through_gmsh(data_dir / "cad" / "die_open.stl", 0.0, false);
  // The first element's first node: after the section's 4 sizes, the block's 3 ints and its
  // size, and the element's tag.
  const std::size_t first_node = bytes.find("$Elements\n") + 10 + 4 * 8 + 3 * 4 + 8 + 8;
  const std::string message = error_of(with_size_at(bytes, first_node, 999999));
  EXPECT_NE(message.find("names node 999999, which has no coordinates"), std::string::npos)
      << message;
}

TEST(MshFile, ElementTypes) {
  EXPECT_EQ(gmsh_nodes_per_element(2), 3);
  EXPECT_EQ(gmsh_nodes_per_element(3), 4);
  EXPECT_EQ(gmsh_nodes_per_element(9), 6);
  EXPECT_EQ(gmsh_type_name(9), "Triangle 6");
  EXPECT_EQ(gmsh_nodes_per_element(15), 1);
  EXPECT_EQ(gmsh_nodes_per_element(1000), 0);
}

TEST(MshFile, ALinkInsteadOfTheFileIsRefused) {
  const fs::path dir = scratch("link");
  std::ofstream(dir / "target.msh") << "$MeshFormat\n";
  fs::create_symlink(dir / "target.msh", dir / "mesh.msh");
  try {
    read_msh41_binary(dir / "mesh.msh", "x.geo", 1e9);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be opened"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sf
