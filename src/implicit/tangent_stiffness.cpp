#include "implicit/tangent_stiffness.hpp"

namespace sf {

TangentStiffness::TangentStiffness(const NodeGraph& graph, const DofMap& dofs, double length_scale,
                                   double relative_step)
    : graph_(graph),
      dofs_(dofs),
      colouring_(colour_distance_two(graph)),
      step_translation_(relative_step * length_scale),
      step_rotation_(relative_step) {}

void TangentStiffness::make_pattern(CscMatrix& k) const {
  // Column (node i, dof d): rows = the free dofs of i's neighbours, in equation order (the
  // neighbours are sorted and equations are numbered node-major, so rows come out sorted).
  const int n = dofs_.equation_count();
  k.n = n;
  k.col_start.assign(static_cast<std::size_t>(n) + 1, 0);
  k.row_index.clear();
  for (int col = 0; col < n; ++col) {
    const int i = dofs_.node_of(col);
    for (int a = graph_.start[i]; a < graph_.start[i + 1]; ++a) {
      const int j = graph_.neighbour[static_cast<std::size_t>(a)];
      for (int dof = 0; dof < 6; ++dof) {
        const int row = dofs_.equation(j, dof);
        if (row >= 0) {
          k.row_index.push_back(row);
        }
      }
    }
    k.col_start[static_cast<std::size_t>(col) + 1] = static_cast<int>(k.row_index.size());
  }
  k.values.assign(k.row_index.size(), 0.0);
}

void TangentStiffness::perturb(int colour, int dof, double step, Matrix3X& du,
                               Matrix3X& dtheta) const {
  // Along the node's own axis where it has a frame (DofMap::add).
  for (int a = colouring_.member_start[static_cast<std::size_t>(colour)];
       a < colouring_.member_start[static_cast<std::size_t>(colour) + 1]; ++a) {
    const int node = colouring_.members[static_cast<std::size_t>(a)];
    if (dofs_.equation(node, dof) >= 0) {
      dofs_.add(node, dof, step, du, dtheta);
    }
  }
}

void TangentStiffness::compute(const StaticShellBody& body, const Matrix3X& du,
                               const Matrix3X& dtheta, CscMatrix& k) {
  if (k.n != dofs_.equation_count() || k.col_start.empty()) {
    make_pattern(k);
  }
  for (int colour = 0; colour < colouring_.colour_count; ++colour) {
    for (int dof = 0; dof < 6; ++dof) {
      const double h = dof < 3 ? step_translation_ : step_rotation_;
      du_ = du;
      dtheta_ = dtheta;
      perturb(colour, dof, h, du_, dtheta_);
      body.compute_forces(du_, dtheta_, f_plus_, m_plus_, trial_);
      du_ = du;
      dtheta_ = dtheta;
      perturb(colour, dof, -h, du_, dtheta_);
      body.compute_forces(du_, dtheta_, f_minus_, m_minus_, trial_);
      const double scale = 0.5 / h;
      for (int a = colouring_.member_start[static_cast<std::size_t>(colour)];
           a < colouring_.member_start[static_cast<std::size_t>(colour) + 1]; ++a) {
        const int i = colouring_.members[static_cast<std::size_t>(a)];
        const int col = dofs_.equation(i, dof);
        if (col < 0) {
          continue;
        }
        int at = k.col_start[static_cast<std::size_t>(col)];
        for (int b = graph_.start[i]; b < graph_.start[i + 1]; ++b) {
          const int j = graph_.neighbour[static_cast<std::size_t>(b)];
          for (int r = 0; r < 6; ++r) {
            if (dofs_.equation(j, r) < 0) {
              continue;
            }
            // The force's component along node j's axis r (its own axes where it has a frame).
            const double plus = dofs_.component(j, r, f_plus_, m_plus_);
            const double minus = dofs_.component(j, r, f_minus_, m_minus_);
            k.values[static_cast<std::size_t>(at++)] = scale * (plus - minus);
          }
        }
      }
    }
  }
}

}  // namespace sf
