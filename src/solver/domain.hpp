#pragma once
// The seam between the physics and the split of the blank over processes (issue 17): what this
// process computes of the blank, and how its partial results become whole. A serial run uses the
// identity (SerialDomain): every element and node, every node's corners summed in their fixed
// order, nothing to add from elsewhere. An MPI rank's domain (parallel/mpi_domain.hpp) computes
// its share of the elements, exchanges its boundary corners before the node sums, all-reduces
// the exact sums, agrees with the other ranks on the smallest step and on the first failure, and
// gathers the state to rank 0 for output. The physics code calls only this interface, never MPI.
#include <array>
#include <climits>
#include <span>
#include <string>
#include <vector>

#include "core/exact_sum.hpp"
#include "core/exact_sums.hpp"
#include "core/types.hpp"
#include "element/corner_forces.hpp"
#include "element/shell_forces.hpp"
#include "element/shell_mass.hpp"

namespace sf {

/// A failure met by one process in a phase that every process goes through together. The
/// processes agree on the one with the lowest key (an element or node index), so that all stop
/// with the same message a serial run gives.
struct PhaseError {
  enum class Kind { none, input, instability, internal };
  Kind kind = Kind::none;
  long key = LONG_MAX;  ///< element or node index; lower wins
  std::string message;

  bool failed() const { return kind != Kind::none; }
};

class Domain {
 public:
  virtual ~Domain() = default;

  /// The elements this process computes (ascending runs); empty: all of them.
  virtual std::span<const ElementRun> element_runs() const = 0;

  /// The nodes whose sums this process counts (each node counted by one process), ascending;
  /// empty: all of them.
  virtual std::span<const int> owned_nodes() const = 0;
  /// Every node this process keeps up to date (its elements' nodes: owned and ghost), ascending;
  /// empty: all of them. The others' entries in the node arrays are left as they were.
  virtual std::span<const int> held_nodes() const = 0;
  /// The nodes this process also keeps up to date without counting them (held by its elements,
  /// owned elsewhere), ascending. Empty in a serial run.
  virtual std::span<const int> ghost_nodes() const = 0;

  /// f and m at the nodes this process holds: each node's corners summed in ascending slot
  /// order (nodes: the part's node-corner lists; corners: kCornerWidth per slot).
  virtual void assemble_corners(const NodeCorners& nodes, std::span<const double> corners,
                                Matrix3X& f, Matrix3X& m) = 0;

  /// mass and inertia at the nodes this process holds, each node's corners added onto them one at
  /// a time in ascending slot order (add_corner_masses: the serial bits); corner_mass:
  /// kMassCornerWidth per slot, written by this process at its elements' slots. Collective.
  virtual void add_corner_masses(const NodeCorners& nodes, std::span<const double> corner_mass,
                                 VectorX& mass, VectorX& inertia) = 0;

  /// f at the nodes this process holds, each node's flagged corner forces added onto it one at a
  /// time in ascending slot order (add_flagged_corner_forces: the serial bits); corners:
  /// kLoadCornerWidth per slot, written by this process at all its elements' slots. Collective.
  virtual void add_flagged_corner_forces(const NodeCorners& nodes, std::span<const double> corners,
                                         Matrix3X& f) = 0;

  /// The contact offset at the nodes this process holds: half the mean thickness (mm) of the
  /// elements around each node (as gather_half_thickness).
  virtual void assemble_half_thickness(const ElementBlocks& blocks, const NodeCorners& nodes,
                                       std::span<const double> thickness,
                                       const VectorX& inverse_element_count,
                                       VectorX& half_thickness) = 0;

  /// Each exact sum made global: the sum of every process's partial sum (collective in a
  /// distributed run: every process calls it with the same number of sums).
  virtual void reduce(std::span<ExactSum> sums) = 0;

  /// The smallest critical step (s) over every process's elements and its element (the lowest
  /// one on a tie), from the per-element steps this process computed (collective).
  virtual StableStep smallest_time_step(std::span<const double> element_dt) = 0;

  /// The failure all processes stop with: the lowest-keyed of every process's `local` (none if
  /// no process failed). Collective: every process calls it, failed or not.
  virtual PhaseError agree(PhaseError local) = 0;

  /// The bitwise OR of every process's `flags` (requests such as "write a checkpoint", "stop"
  /// that one process may have received alone). Collective.
  virtual int agree_flags(int flags) = 0;

  /// The whole field on the output process (is_root): each entry written by its owner. data
  /// holds `width` doubles per node (gather_nodes) or per element (gather_elements), full size.
  /// Collective; no-ops in a serial run.
  virtual void gather_nodes(std::span<double> data, int width) = 0;
  virtual void gather_elements(std::span<double> data, int width) = 0;

  /// Every process's `values` (the same count on each), concatenated in process order on the
  /// output process (empty elsewhere). Collective.
  virtual std::vector<double> gather_values(std::span<const double> values) = 0;

  /// s, the wall time this process spent in messages so far (its exchanges, reductions and
  /// gathers, waiting for the others included): the phase times less this are its own work.
  virtual double communication_seconds() const = 0;

  /// Whether this process writes the results and prints (rank 0).
  virtual bool is_root() const = 0;
  /// Processes sharing the blank (1: serial).
  virtual int processes() const = 0;
};

/// One process computes everything: the identity.
class SerialDomain final : public Domain {
 public:
  std::span<const ElementRun> element_runs() const override { return {}; }
  std::span<const int> owned_nodes() const override { return {}; }
  std::span<const int> held_nodes() const override { return {}; }
  std::span<const int> ghost_nodes() const override { return {}; }
  void assemble_corners(const NodeCorners& nodes, std::span<const double> corners, Matrix3X& f,
                        Matrix3X& m) override {
    gather_corner_forces(nodes, corners, f, m);
  }
  void add_corner_masses(const NodeCorners& nodes, std::span<const double> corner_mass,
                         VectorX& mass, VectorX& inertia) override {
    sf::add_corner_masses(nodes, corner_mass, mass, inertia);
  }
  void add_flagged_corner_forces(const NodeCorners& nodes, std::span<const double> corners,
                                 Matrix3X& f) override {
    sf::add_flagged_corner_forces(nodes, corners, f);
  }
  void assemble_half_thickness(const ElementBlocks& blocks, const NodeCorners& nodes,
                               std::span<const double> thickness,
                               const VectorX& inverse_element_count,
                               VectorX& half_thickness) override {
    gather_half_thickness(nodes, thickness, inverse_element_count, half_thickness);
  }
  void reduce(std::span<ExactSum> /*sums*/) override {}
  StableStep smallest_time_step(std::span<const double> element_dt) override {
    return sf::smallest_time_step(element_dt);
  }
  PhaseError agree(PhaseError local) override { return local; }
  int agree_flags(int flags) override { return flags; }
  void gather_nodes(std::span<double> /*data*/, int /*width*/) override {}
  void gather_elements(std::span<double> /*data*/, int /*width*/) override {}
  std::vector<double> gather_values(std::span<const double> values) override {
    return {values.begin(), values.end()};
  }
  double communication_seconds() const override { return 0.0; }
  bool is_root() const override { return true; }
  int processes() const override { return 1; }
};

/// The K exact sums over all nodes of terms(i, t) (node i's K terms into t), each node counted
/// by the one process that owns it, made global (collective). Only owned nodes are visited.
template <int K, typename Terms>
std::array<ExactSum, K> sum_over_nodes(Domain& domain, long n_nodes, const Terms& terms) {
  const std::span<const int> owned = domain.owned_nodes();
  std::array<ExactSum, K> sums =
      owned.empty() ? sum_exactly<K>(n_nodes, terms)
                    : sum_exactly<K>(static_cast<long>(owned.size()), [&](long j, double* t) {
                        terms(static_cast<long>(owned[static_cast<std::size_t>(j)]), t);
                      });
  domain.reduce(sums);
  return sums;
}

}  // namespace sf
