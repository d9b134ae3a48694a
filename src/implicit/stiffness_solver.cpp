#include "implicit/stiffness_solver.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/log.hpp"

namespace sf {

StiffnessSolver::StiffnessSolver(ImplicitConfig::LinearSolver choice) : choice_(choice) {}

void StiffnessSolver::account(const SparseFactorization& f, int analyses_before) {
  const FactorizationStats& s = f.stats();
  if (s.analyses > analyses_before) {  // analyse_seconds is the last analysis's: count it once
    totals_.analyse_seconds += s.analyse_seconds;
  }
  totals_.factor_seconds += s.factor_seconds;
  totals_.factorizations += 1;
  if (s.method == FactorizationMethod::cholmod) {
    totals_.cholmod_factorizations += 1;
  } else {
    totals_.umfpack_factorizations += 1;
  }
}

void StiffnessSolver::factorize(CscMatrix& k) {
  using Choice = ImplicitConfig::LinearSolver;
  const double asymmetry = k.asymmetry();
  totals_.max_asymmetry = std::max(totals_.max_asymmetry, asymmetry);
  bool use_cholmod = choice_ == Choice::cholmod ||
                     (choice_ == Choice::automatic && asymmetry < kSymmetryTolerance);
  if (use_cholmod) {
    if (!cholmod_) {
      cholmod_ = make_factorization(FactorizationMethod::cholmod);
    }
    k.symmetrize();
    try {
      const int analyses = cholmod_->stats().analyses;
      cholmod_->factorize(k);
      account(*cholmod_, analyses);
      last_ = cholmod_.get();
      return;
    } catch (const SingularSystemError& e) {
      if (choice_ == Choice::cholmod) {
        throw;
      }
      log_info("  tangent not positive definite for CHOLMOD ({}); UMFPACK takes it\n", e.what());
    }
  }
  if (!umfpack_) {
    umfpack_ = make_factorization(FactorizationMethod::umfpack);
  }
  const int analyses = umfpack_->stats().analyses;
  umfpack_->factorize(k);
  account(*umfpack_, analyses);
  last_ = umfpack_.get();
}

void StiffnessSolver::solve(std::span<const double> b, std::span<double> x) {
  if (!last_) {
    throw std::logic_error("StiffnessSolver::solve before factorize");
  }
  last_->solve(b, x);
  totals_.solve_seconds += last_->stats().solve_seconds;
}

const FactorizationStats& StiffnessSolver::last_stats() const {
  if (!last_) {
    throw std::logic_error("StiffnessSolver::last_stats before factorize");
  }
  return last_->stats();
}

}  // namespace sf
