#pragma once
// The element corners of a shell part and their sum at the nodes (issue 17: deterministic
// assembly). The element pass writes each element's nodal forces and moments into its own corner
// slots, never into shared nodal arrays, so elements can run on any thread; every node then sums
// its corners in one fixed order, ascending corner slot (quads, then triangles, in element
// order), starting from zero: the order and the bits of a serial scatter into zeroed arrays.
#include <span>
#include <vector>

#include "core/types.hpp"
#include "element/element_block.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Values per corner slot: force (N) and moment (N mm), global components.
inline constexpr int kCornerWidth = 6;

/// Corner slots in all: each element's corners, block after block (ElementBlock::corner_slot).
inline int corner_count(const ShellPart& part) {
  return element_blocks(part).corner_count();
}

/// Writes an element's N corners, forces f (N) and moments m (N mm) in global components, to its
/// consecutive corner slots from `corners` (kCornerWidth values each).
template <int N>
inline void store_corners(const Eigen::Matrix<double, 3, N>& f,
                          const Eigen::Matrix<double, 3, N>& m, double* corners) {
  for (int i = 0; i < N; ++i) {
    double* c = corners + kCornerWidth * i;
    c[0] = f(0, i);
    c[1] = f(1, i);
    c[2] = f(2, i);
    c[3] = m(0, i);
    c[4] = m(1, i);
    c[5] = m(2, i);
  }
}

/// Each node's corner slots, ascending (compressed rows: node i's slots are
/// slots[offsets[i] .. offsets[i + 1])). Built once per part.
struct NodeCorners {
  std::vector<int> offsets;
  std::vector<int> slots;
  /// The element of each of `slots` (state index): what the per-cycle gathers of element values
  /// read, instead of finding each slot's block.
  std::vector<int> elements;

  int node_count() const { return offsets.empty() ? 0 : static_cast<int>(offsets.size()) - 1; }
};

/// The lists of a blank given as its element blocks. Throws std::invalid_argument when a node id
/// is outside [0, n_nodes).
NodeCorners build_node_corners(const ElementBlocks& blocks, int n_nodes);
/// The same for a part (its blocks).
inline NodeCorners build_node_corners(const ShellPart& part, int n_nodes) {
  return build_node_corners(element_blocks(part), n_nodes);
}

/// f.col(i) and m.col(i) = the sum of node i's corners' forces and moments (0 + c1 + c2 + ...,
/// in slot order) from corners (kCornerWidth per slot). Threads share out the nodes.
void gather_corner_forces(const NodeCorners& nodes, std::span<const double> corners, Matrix3X& f,
                          Matrix3X& m);

/// Doubles per corner slot of the masses an element adds to its nodes (mass scaling): the mass
/// (tonne) and the rotational inertia (tonne mm^2) each of its nodes receives.
inline constexpr int kMassCornerWidth = 2;

/// mass[i] += c1 + ..., inertia[i] likewise, one corner at a time onto the value the node has, in
/// slot order, from corner_mass (kMassCornerWidth per slot; 0 at the slots of elements that add
/// nothing, which leaves the sum's bits as they are): the bits of adding each element's share
/// to its nodes in element order. Threads share out the nodes.
void add_corner_masses(const NodeCorners& nodes, std::span<const double> corner_mass, VectorX& mass,
                       VectorX& inertia);

/// Doubles per corner slot of a load the elements put on their nodes (pressure): the force (N)
/// and a flag, 1 where the element carries the load, 0 where it does not.
inline constexpr int kLoadCornerWidth = 4;

/// f.col(i) += each of node i's flagged corner forces, one at a time in slot order, onto the
/// value the node has (corners: kLoadCornerWidth per slot): the bits of adding each loaded
/// element's share to its nodes in element order. Threads share out the nodes.
void add_flagged_corner_forces(const NodeCorners& nodes, std::span<const double> corners,
                               Matrix3X& f);

/// half_thickness[i] = (sum over node i's corners of half their element's thickness) *
/// inverse_element_count[i]: the mean half thickness around the node (mm), the contact offset.
void gather_half_thickness(const NodeCorners& nodes, std::span<const double> thickness,
                           const VectorX& inverse_element_count, VectorX& half_thickness);

}  // namespace sf
