// Fuzz target: the mesh reader for .msh files (src/meshing/gmsh_reader.cpp): gmsh's MSH parser in
// its sandboxed child (one per input: a crash there is an InputError here), the MSH 4.1 file it
// hands back read by sheetform's parser, then sheetform's own code on the model: physical groups,
// part meshes (element types, orientation propagation, degenerate elements) and node groups. Each
// input is written as mesh.msh into a work folder. Only .msh files: .geo text goes to the geo
// scanner (fuzz_geo_safety.cpp).
// Checks: every reader call returns or throws sf::InputError, nothing else; a part mesh it returns
// has in-range connectivity and one gmsh tag per node.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/errors.hpp"
#include "fuzz_support.hpp"
#include "meshing/gmsh_reader.hpp"

namespace {

void check_part(const sf::PartMesh& part) {
  const auto n = part.nodes.cols();
  if (static_cast<std::size_t>(n) != part.gmsh_node_tags.size()) {
    sf::fuzz::broken("part mesh: node count and gmsh tags differ", part.name);
  }
  for (Eigen::Index e = 0; e < part.quads.cols(); ++e) {
    for (int k = 0; k < 4; ++k) {
      if (part.quads(k, e) < 0 || part.quads(k, e) >= n) {
        sf::fuzz::broken("part mesh: quad node out of range", part.name);
      }
    }
  }
  for (Eigen::Index e = 0; e < part.triangles.cols(); ++e) {
    for (int k = 0; k < 3; ++k) {
      if (part.triangles(k, e) < 0 || part.triangles(k, e) >= n) {
        sf::fuzz::broken("part mesh: triangle node out of range", part.name);
      }
    }
  }
}

void read_mesh(const std::filesystem::path& file) {
  const sf::GmshModel model = sf::load_gmsh_model(file, 0.0, false);
  for (const auto& group : model.groups) {
    if (group.dim != 2 || group.name.empty()) {
      continue;
    }
    try {
      const sf::PartMesh part = sf::extract_part_mesh(model, group.name, "blank");
      check_part(part);
      for (const auto& other : model.groups) {
        if (other.name.empty()) {
          continue;
        }
        try {
          const sf::NodeGroup nodes = sf::extract_node_group(model, part, other.name);
          for (const int node : nodes.nodes) {
            if (node < 0 || node >= part.nodes.cols()) {
              sf::fuzz::broken("node group: node out of range", other.name);
            }
          }
        } catch (const sf::InputError&) {
        }
      }
    } catch (const sf::InputError&) {
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  sf::fuzz::quiet();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = sf::fuzz::write_input("mesh.msh", data, size);
  try {
    read_mesh(file);
  } catch (const sf::InputError&) {
    return 0;
  } catch (const std::exception& e) {
    sf::fuzz::unexpected_exception("the mesh reader", &e);
  } catch (...) {
    sf::fuzz::unexpected_exception("the mesh reader", nullptr);
  }
  return 0;
}
