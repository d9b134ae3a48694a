#pragma once
// The seam between the physics and the split of the blank over processes (issue 17): what this
// process computes of the blank, and how its partial results become whole. A serial run uses the
// identity (SerialDomain): every element, every node's corners summed in their fixed order, and
// nothing to add from elsewhere. An MPI rank's domain (the next step of issue 17, src/parallel)
// gives its element runs, exchanges its boundary corners before the node sums and all-reduces
// the exact sums. The physics code calls only this interface, never MPI.
#include <span>

#include "core/exact_sum.hpp"
#include "core/types.hpp"
#include "element/corner_forces.hpp"
#include "element/shell_forces.hpp"

namespace sf {

class Domain {
 public:
  virtual ~Domain() = default;

  /// The elements this process computes (ascending runs); empty: all of them.
  virtual std::span<const ElementRun> element_runs() const = 0;

  /// f and m at the nodes this process holds: each node's corners summed in ascending slot
  /// order (nodes: the part's node-corner lists; corners: kCornerWidth per slot).
  virtual void assemble_corners(const NodeCorners& nodes, std::span<const double> corners,
                                Matrix3X& f, Matrix3X& m) = 0;

  /// Each exact sum made global: the sum of every process's partial sum (collective in a
  /// distributed run: every process calls it with the same number of sums).
  virtual void reduce(std::span<ExactSum> sums) = 0;
};

/// One process computes everything: the identity.
class SerialDomain final : public Domain {
 public:
  std::span<const ElementRun> element_runs() const override { return {}; }
  void assemble_corners(const NodeCorners& nodes, std::span<const double> corners, Matrix3X& f,
                        Matrix3X& m) override {
    gather_corner_forces(nodes, corners, f, m);
  }
  void reduce(std::span<ExactSum> /*sums*/) override {}
};

}  // namespace sf
