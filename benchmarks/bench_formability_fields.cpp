// Benchmark of the formability result fields (not a test): the cost of computing them for one
// frame (solver/formability_output.hpp) on a 100 x 100 plate of 1 mm quadrilaterals, domed and
// stretched (so that every element is off its reference shape), against the cost of the cycle
// they are not part of. Prints ns per element per frame: the fastest of 5 batches.
//
// Usage: bench_formability_fields [frames = 20]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>

#include "bench_host.hpp"
#include "solver/formability_output.hpp"

namespace {

using namespace sf;

constexpr int kCells = 100;  // elements per side, 1 mm each

using bench::machine_name;

Model make_plate_model() {
  Model model;
  const int n = kCells + 1;
  model.blank.mesh.nodes.resize(3, n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      model.blank.mesh.nodes.col(j * n + i) = Vec3(i, j, 0.0);
    }
  }
  model.blank.part.quads.resize(4, kCells * kCells);
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      const int a = j * n + i;
      model.blank.part.quads.col(j * kCells + i) << a, a + 1, a + n + 1, a + n;
    }
  }
  model.blank.part.triangles.resize(3, 0);
  model.blank.parts = {{"blank", 1.0}};
  model.formability.part_curves = {keeler_brazier_curve(0.2, 1.0)};
  return model;
}

}  // namespace

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20;
  const Model model = make_plate_model();
  Matrix3X x = model.blank.mesh.nodes;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {  // a dome 10 mm high, stretched 20 % along x
    const double u = x(0, i) / kCells - 0.5, v = x(1, i) / kCells - 0.5;
    x(0, i) *= 1.2;
    x(2, i) = 10.0 * (1.0 - 4.0 * (u * u + v * v));
  }
  const std::vector<double> thickness(kCells * kCells, 0.85);
  FormabilityEvaluator evaluator(model);
  FormabilityFields fields;
  double best = std::numeric_limits<double>::infinity();
  for (int batch = 0; batch < 5; ++batch) {
    const auto start = std::chrono::steady_clock::now();
    for (int f = 0; f < frames; ++f) {
      evaluator.evaluate(model, x, thickness, fields);
    }
    const std::chrono::duration<double, std::nano> took = std::chrono::steady_clock::now() - start;
    best = std::min(best, took.count() / (static_cast<double>(frames) * kCells * kCells));
  }
  std::printf("bench_formability_fields on %s: %d x %d quads, %d frames per batch\n",
              machine_name().c_str(), kCells, kCells, frames);
  std::printf("formability fields: %.1f ns per element per frame (zone of element 0: %g)\n", best,
              fields.zone[0]);
  return 0;
}
