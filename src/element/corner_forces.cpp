#include "element/corner_forces.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace sf {

namespace {
// Below this many nodes a gather runs on one thread (a parallel region costs microseconds).
constexpr int kMinParallelNodes = 1024;
}  // namespace

NodeCorners build_node_corners(const ElementBlocks& blocks, int n_nodes) {
  NodeCorners list;
  list.offsets.assign(static_cast<std::size_t>(n_nodes) + 1, 0);
  for (const ElementBlock& block : blocks) {
    for (int slot = block.first_slot; slot < block.slot_end(); ++slot) {
      const int node = block.node_of_slot(slot);
      if (node < 0 || node >= n_nodes) {
        throw std::invalid_argument("build_node_corners: element node " + std::to_string(node) +
                                    " outside [0, " + std::to_string(n_nodes) + ")");
      }
      ++list.offsets[static_cast<std::size_t>(node) + 1];
    }
  }
  for (int i = 0; i < n_nodes; ++i) {
    list.offsets[static_cast<std::size_t>(i) + 1] += list.offsets[static_cast<std::size_t>(i)];
  }
  // Filled in ascending slot order, so each node's slots come out ascending.
  std::vector<int> next(list.offsets.begin(), list.offsets.end() - 1);
  list.slots.resize(static_cast<std::size_t>(blocks.corner_count()));
  list.elements.resize(list.slots.size());
  for (const ElementBlock& block : blocks) {
    for (int slot = block.first_slot; slot < block.slot_end(); ++slot) {
      const auto node = static_cast<std::size_t>(block.node_of_slot(slot));
      const auto j = static_cast<std::size_t>(next[node]++);
      list.slots[j] = slot;
      list.elements[j] = block.element_of_slot(slot);
    }
  }
  return list;
}

void gather_corner_forces(const NodeCorners& nodes, std::span<const double> corners, Matrix3X& f,
                          Matrix3X& m) {
  const int n = nodes.node_count();
  const int* offsets = nodes.offsets.data();
  const int* slots = nodes.slots.data();
  const double* c = corners.data();
  double* fd = f.data();
  double* md = m.data();
#pragma omp parallel for schedule(static) if (n >= kMinParallelNodes)
  for (int i = 0; i < n; ++i) {
    double sum[kCornerWidth] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (int j = offsets[i]; j < offsets[i + 1]; ++j) {
      const double* corner = c + kCornerWidth * static_cast<std::ptrdiff_t>(slots[j]);
      for (int k = 0; k < kCornerWidth; ++k) {
        sum[k] += corner[k];
      }
    }
    double* fi = fd + 3 * static_cast<std::ptrdiff_t>(i);
    double* mi = md + 3 * static_cast<std::ptrdiff_t>(i);
    for (int k = 0; k < 3; ++k) {
      fi[k] = sum[k];
      mi[k] = sum[3 + k];
    }
  }
}

void add_corner_masses(const NodeCorners& nodes, std::span<const double> corner_mass, VectorX& mass,
                       VectorX& inertia) {
  const int n = nodes.node_count();
  const int* offsets = nodes.offsets.data();
  const int* slots = nodes.slots.data();
  const double* c = corner_mass.data();
#pragma omp parallel for schedule(static) if (n >= kMinParallelNodes)
  for (int i = 0; i < n; ++i) {
    for (int j = offsets[i]; j < offsets[i + 1]; ++j) {
      const double* corner = c + kMassCornerWidth * static_cast<std::ptrdiff_t>(slots[j]);
      mass[i] += corner[0];
      inertia[i] += corner[1];
    }
  }
}

void add_flagged_corner_forces(const NodeCorners& nodes, std::span<const double> corners,
                               Matrix3X& f) {
  const int n = nodes.node_count();
  const int* offsets = nodes.offsets.data();
  const int* slots = nodes.slots.data();
  const double* c = corners.data();
#pragma omp parallel for schedule(static) if (n >= kMinParallelNodes)
  for (int i = 0; i < n; ++i) {
    for (int j = offsets[i]; j < offsets[i + 1]; ++j) {
      const double* corner = c + kLoadCornerWidth * static_cast<std::ptrdiff_t>(slots[j]);
      if (corner[3] != 0.0) {
        f.col(i) += Vec3(corner[0], corner[1], corner[2]);
      }
    }
  }
}

void gather_half_thickness(const NodeCorners& nodes, std::span<const double> thickness,
                           const VectorX& inverse_element_count, VectorX& half_thickness) {
  const int n = nodes.node_count();
  const int* offsets = nodes.offsets.data();
  const int* elements = nodes.elements.data();
  const double* t = thickness.data();
#pragma omp parallel for schedule(static) if (n >= kMinParallelNodes)
  for (int i = 0; i < n; ++i) {
    double sum = 0.0;
    for (int j = offsets[i]; j < offsets[i + 1]; ++j) {
      sum += 0.5 * t[elements[j]];
    }
    half_thickness[i] = sum * inverse_element_count[i];
  }
}

}  // namespace sf
