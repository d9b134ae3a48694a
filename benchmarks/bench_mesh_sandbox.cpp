// What the sandbox costs per mesh source (docs/security.md): load_gmsh_model (gmsh in a confined
// child, the mesh handed back as MSH 4.1 binary and parsed here) against gmsh run in this process
// and read through its API, as sheetform did before, on the bundled sources. Prints ms per read
// for both, the difference, and the mesh's size. A benchmark, not a test: it checks nothing.
//   build/benchmarks/bench_mesh_sandbox [repetitions]
#include <fmt/core.h>

#include <gmsh.h>
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "meshing/gmsh_reader.hpp"

namespace {

namespace fs = std::filesystem;

struct Source {
  std::string label;
  fs::path file;
  double element_size;
  bool recombine;
};

// gmsh in this process: open, mesh where needed, read every group's elements and nodes.
std::size_t in_process(const Source& s) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.NumThreads", 1);
  if (s.element_size > 0) {
    gmsh::option::setNumber("Mesh.MeshSizeMax", s.element_size);
  }
  gmsh::open(s.file.string());
  const std::string ext = s.file.extension().string();
  if (ext == ".geo" || ext == ".step") {
    if (s.recombine) {
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
    }
    gmsh::model::mesh::generate(2);
  }
  std::vector<std::size_t> tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
  std::size_t elements = 0;
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, 2);
  for (const auto& [dim, tag] : entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, tag);
    for (const auto& t : element_tags) {
      elements += t.size();
    }
  }
  gmsh::finalize();
  return elements;
}

std::size_t sandboxed(const Source& s) {
  sf::MeshImportOptions import;
  import.group = "tool";
  const sf::GmshModel model = sf::load_gmsh_model(s.file, s.element_size, s.recombine, {}, import);
  std::size_t elements = 0;
  for (const auto& g : model.groups) {
    if (g.dim == 2) {
      for (const auto& b : g.elements) {
        elements += b.element_tags.size();
      }
    }
  }
  return elements;
}

template <typename F>
double best_ms(int repetitions, F&& f, std::size_t& elements) {
  double best = 1e300;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    elements = f();
    best = std::min(
        best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                  .count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const fs::path root = SF_SOURCE_DIR;
  const fs::path cup = root / "cases" / "square_cup_aluminium";
  const std::vector<Source> sources = {
      {"square cup blank .geo (quads)", cup / "blank.geo", 0.0, true},
      {"square cup die .geo", cup / "die.geo", 0.0, false},
      {"square cup die .msh", cup / "die.msh", 0.0, false},
      {"punch STEP, 2 mm", root / "tests" / "data" / "cad" / "punch.step", 2.0, false},
      {"open die STL", root / "tests" / "data" / "cad" / "die_open.stl", 0.0, false},
  };
  fmt::print("Mesh source reading, best of {} (ms): gmsh in this process vs in the sandbox\n",
             repetitions);
  fmt::print("{:<32} {:>9} {:>11} {:>11} {:>11}\n", "source", "elements", "in-process", "sandboxed",
             "difference");
  for (const Source& s : sources) {
    std::size_t direct_elements = 0, sandbox_elements = 0;
    const double direct = best_ms(
        repetitions, [&] { return in_process(s); }, direct_elements);
    const double boxed = best_ms(
        repetitions, [&] { return sandboxed(s); }, sandbox_elements);
    fmt::print("{:<32} {:>9} {:>11.1f} {:>11.1f} {:>+11.1f}\n", s.label, sandbox_elements, direct,
               boxed, boxed - direct);
  }
  return 0;
}
