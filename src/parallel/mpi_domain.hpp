#pragma once
// An MPI rank's share of the blank (issue 17, item 3; research/parallel.md §6.3): the solver's
// Domain (solver/domain.hpp) for a run of several ranks.
//
// Every rank builds the whole model and keeps full-size node and element arrays, but computes
// only its elements (a METIS part of the blank, made on rank 0 and broadcast) and keeps only the
// nodes they touch up to date: the nodes it owns (counted in every node sum by it alone) and its
// ghost nodes (owned by a neighbour, updated here too from the same bits). Each cycle it sends its
// neighbours its corners at the nodes they share and sums every held node's corners in the
// serial order (rank_plan.hpp), so a held node's force has the serial bits; the exact sums are
// all-reduced exactly (exact_allreduce.hpp). The rigid tools are replicated: contact needs no
// message beyond the all-reduced reactions. Rank 0 gathers the owned entries for output.
//
// Memory per rank is that of the whole model (the arrays are not renumbered per rank): simple,
// and enough for workstation and small-cluster runs; time per rank scales with its share.
#include <mpi.h>

#include <vector>

#include "parallel/corner_exchange.hpp"
#include "parallel/rank_plan.hpp"
#include "solver/domain.hpp"

namespace sf {

class MpiDomain final : public Domain {
 public:
  /// Partitions the blank (quads then triangles, as the ShellPart; n_nodes nodes) over comm's
  /// ranks; collective. Throws std::invalid_argument naming the problem when the blank has fewer
  /// elements than there are ranks.
  MpiDomain(const QuadConn& quads, const TriConn& triangles, int n_nodes, MPI_Comm comm);

  std::span<const ElementRun> element_runs() const override { return runs_; }
  std::span<const int> owned_nodes() const override { return plan_.owned_nodes; }
  std::span<const int> held_nodes() const override { return plan_.nodes; }
  std::span<const int> ghost_nodes() const override { return ghost_nodes_; }
  void assemble_corners(const NodeCorners& nodes, std::span<const double> corners, Matrix3X& f,
                        Matrix3X& m) override;
  void add_corner_masses(const NodeCorners& nodes, std::span<const double> corner_mass,
                         VectorX& mass, VectorX& inertia) override;
  void add_flagged_corner_forces(const NodeCorners& nodes, std::span<const double> corners,
                                 Matrix3X& f) override;
  void assemble_half_thickness(const ElementBlocks& blocks, const NodeCorners& nodes,
                               std::span<const double> thickness,
                               const VectorX& inverse_element_count,
                               VectorX& half_thickness) override;
  void reduce(std::span<ExactSum> sums) override;
  StableStep smallest_time_step(std::span<const double> element_dt) override;
  PhaseError agree(PhaseError local) override;
  int agree_flags(int flags) override;
  void gather_nodes(std::span<double> data, int width) override;
  void gather_elements(std::span<double> data, int width) override;
  std::vector<double> gather_values(std::span<const double> values) override;
  double communication_seconds() const override { return communication_seconds_; }
  bool is_root() const override { return plan_.rank == 0; }
  int processes() const override { return plan_.ranks; }

  const RankPlan& plan() const { return plan_; }

 private:
  // Rank 0's view of every rank's owned entries (for the gathers): counts per rank, their
  // displacements and the concatenated index lists (empty on other ranks).
  struct RootLayout {
    std::vector<int> counts;
    std::vector<int> displacements;
    std::vector<int> indices;
  };
  static RootLayout gather_layout(std::span<const int> mine, MPI_Comm comm, int rank, int ranks);
  void gather(std::span<double> data, int width, std::span<const int> mine,
              const RootLayout& layout);

  MPI_Comm comm_;
  RankPlan plan_;
  std::vector<ElementRun> runs_;
  std::vector<int> ghost_nodes_;
  CornerExchange forces_;     ///< kCornerWidth per corner
  CornerExchange thickness_;  ///< 1 per corner
  CornerExchange masses_;     ///< kMassCornerWidth per corner (mass scaling)
  CornerExchange loads_;      ///< kLoadCornerWidth per corner (pressure loads)
  std::vector<double> received_forces_;
  std::vector<double> received_masses_;
  std::vector<double> received_loads_;
  std::vector<double> received_thickness_;
  std::vector<double> thickness_corners_;  ///< half the element's thickness at its own slots
  RootLayout node_layout_;
  RootLayout element_layout_;
  std::vector<double> send_;     ///< gather scratch
  std::vector<double> receive_;  ///< gather scratch (rank 0)
  double communication_seconds_ = 0.0;
};

}  // namespace sf
