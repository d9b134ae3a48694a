#include "material/general_plasticity.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "material/plane_stress_kernels.hpp"

namespace sf {
namespace {

using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat4 = Eigen::Matrix<double, 4, 4>;

constexpr double kTolerance = 1e-10;  // of the flow stress, on both residuals
constexpr int kMaxIterations = 100;
constexpr int kMaxHalvings = 40;

// The return's unknowns (relative stress, plastic multiplier) and everything its residual and
// Jacobian need, evaluated at one iterate.
struct Iterate {
  Vec3 eta = Vec3::Zero();
  double d_lambda = 0.0;
  EquivalentStress eq;
  FlowStress flow{};         // flow stress at eps_p + d_lambda, with the rate factor
  double static_flow = 0.0;  // MPa, the rate-free flow stress sigma_y(eps_p + d_lambda)
  double B = 0.0;            // sum_i C_i d_lambda / (sigma_y (1 + gamma_i d_lambda))
  double dB = 0.0;           // d B / d d_lambda
  Vec3 decayed_sum;          // sum_i alpha_n,i / (1 + gamma_i d_lambda)
  Vec3 d_decayed_sum;        // its d / d d_lambda
  Vec3 r_stress;             // residual of the stress equation, MPa
  double r_yield = 0.0;      // residual of the yield condition, MPa

  double merit() const { return r_stress.squaredNorm() + r_yield * r_yield; }
};

class Return {
 public:
  Return(const GeneralPlasticity& law, const GeneralPlasticityState& old, const Vec3& trial,
         double dt)
      : law_(law),
        old_(old),
        trial_(trial),
        C_(plane_stress_stiffness(law.E, law.nu)),
        rate_D_dt_(law.rate.active() && dt > 0.0 ? law.rate.D * dt : 0.0) {}

  // The rate-free flow stress f at eps_p + d_lambda times the Cowper-Symonds factor
  // 1 + (d_lambda / (D dt))^(1/q) when the rate dependence is on; the slope d / d d_lambda
  // includes the factor's.
  FlowStress with_rate(const FlowStress& f, double d_lambda) const {
    if (rate_D_dt_ == 0.0) {
      return f;
    }
    if (!(d_lambda > 0.0)) {
      // The factor's slope is infinite at d_lambda = 0 for q > 1: flagged, bounded by the caller.
      return {f.stress, std::numeric_limits<double>::infinity()};
    }
    const double power = std::pow(d_lambda / rate_D_dt_, 1.0 / law_.rate.q);
    const double d_power = power / (law_.rate.q * d_lambda);
    return {f.stress * (1.0 + power), f.slope * (1.0 + power) + f.stress * d_power};
  }

  Iterate evaluate(const Vec3& eta, double d_lambda) const {
    Iterate it;
    it.eta = eta;
    it.d_lambda = d_lambda;
    it.eq = equivalent_stress(law_.criterion, eta);
    const FlowStress rate_free = evaluate_hardening(law_.hardening, old_.eps_p + d_lambda);
    it.static_flow = rate_free.stress;
    it.flow = with_rate(rate_free, d_lambda);
    // An infinite initial slope (Ludwik with n < 1, the rate factor at d_lambda = 0) only steers
    // Newton: bound it.
    if (!std::isfinite(it.flow.slope)) {
      it.flow.slope = 1e3 * law_.E;
    }
    const double y = it.flow.stress;
    it.decayed_sum.setZero();
    it.d_decayed_sum.setZero();
    for (int i = 0; i < law_.kinematic.count; ++i) {
      const BackStressTerm& t = law_.kinematic.terms[i];
      const double q = 1.0 / (1.0 + t.gamma * d_lambda);
      const double beta = t.C * d_lambda * q / y;
      it.B += beta;
      it.dB += t.C * q * q / y - beta * it.flow.slope / y;
      it.decayed_sum += q * old_.back[i];
      it.d_decayed_sum -= t.gamma * q * q * old_.back[i];
    }
    it.r_stress = (1.0 + it.B) * eta + it.decayed_sum - trial_ + d_lambda * (C_ * it.eq.gradient);
    it.r_yield = it.eq.value - y;
    return it;
  }

  Mat4 jacobian(const Iterate& it) const {
    Mat4 J;
    J.topLeftCorner<3, 3>() = (1.0 + it.B) * Mat3::Identity() + it.d_lambda * (C_ * it.eq.hessian);
    J.topRightCorner<3, 1>() = it.dB * it.eta + it.d_decayed_sum + C_ * it.eq.gradient;
    J.bottomLeftCorner<1, 3>() = it.eq.gradient.transpose();
    J(3, 3) = -it.flow.slope;
    return J;
  }

  bool converged(const Iterate& it) const {
    const double scale = kTolerance * it.flow.stress;
    return it.r_stress.norm() <= scale && std::abs(it.r_yield) <= scale;
  }

  const Mat3& stiffness() const { return C_; }

 private:
  const GeneralPlasticity& law_;
  const GeneralPlasticityState& old_;
  Vec3 trial_;
  Mat3 C_;
  double rate_D_dt_;  // D dt of the rate dependence (-: D in 1/s, dt in s); 0 = rate-free
};

// The law's name in a failure's text: the criterion's, in plane stress.
const char* law_name(const YieldCriterion& criterion) {
  struct Visitor {
    const char* operator()(const VonMisesCriterion&) const { return "von Mises plane stress"; }
    const char* operator()(const Hill48Criterion&) const { return "Hill48 plane stress"; }
    const char* operator()(const Yld2000Criterion&) const { return "Yld2000-2d plane stress"; }
    const char* operator()(const Yld89Criterion&) const { return "Yld89 plane stress"; }
  };
  return std::visit(Visitor{}, criterion);
}

MaterialFailure not_converged(const GeneralPlasticity& law, const Vec3& trial, const Iterate& it) {
  return {MaterialFailure::Kind::general_return_not_converged,
          law_name(law.criterion),
          {trial(0), trial(1), trial(2), std::sqrt(it.merit())}};
}

}  // namespace

GeneralPlasticityUpdate GeneralPlasticity::update(const GeneralPlasticityState& old,
                                                  const Vec3& d_strain, Mat3* tangent,
                                                  double flow_at_old, double dt) const {
  MaterialFailure failure;
  const GeneralPlasticityUpdate up =
      update_or_fail(old, d_strain, failure, tangent, flow_at_old, dt);
  throw_if_failed(failure);
  return up;
}

GeneralPlasticityUpdate GeneralPlasticity::update_or_fail(const GeneralPlasticityState& old,
                                                          const Vec3& d_strain,
                                                          MaterialFailure& failure, Mat3* tangent,
                                                          double flow_at_old, double dt) const {
  const Vec3 trial = elastic_trial(E, nu, old.stress, d_strain);
  if (!trial.allFinite()) {
    failure = {MaterialFailure::Kind::non_finite_trial_stress, law_name(criterion)};
    return {};
  }
  Vec3 back_sum = Vec3::Zero();
  for (int i = 0; i < kinematic.count; ++i) {
    back_sum += old.back[i];
  }
  const Vec3 eta_trial = trial - back_sum;
  const double flow_n =
      std::isnan(flow_at_old) ? evaluate_hardening(hardening, old.eps_p).stress : flow_at_old;
  GeneralPlasticityUpdate up;
  if (equivalent_stress_value(criterion, eta_trial) <= flow_n) {
    up.flow_stress = flow_n;
    up.state = old;
    up.state.stress = trial;
    up.d_ezz = through_thickness_increment(E, nu, d_strain, old.stress, trial);
    if (tangent) {
      *tangent = plane_stress_stiffness(E, nu);
    }
    return up;
  }
  const Return ret(*this, old, trial, dt);
  // First iterate: one cutting-plane step from the trial state (Simo & Ortiz 1985).
  Iterate it = ret.evaluate(eta_trial, 0.0);
  {
    const Vec3 Cn = ret.stiffness() * it.eq.gradient;
    double kin = 0.0;
    for (int i = 0; i < kinematic.count; ++i) {
      kin += kinematic.terms[i].C;
    }
    const double d_lambda = it.r_yield / (it.eq.gradient.dot(Cn) + it.flow.slope + kin);
    const Iterate first = ret.evaluate(eta_trial - d_lambda * Cn, d_lambda);
    if (first.merit() < it.merit()) {
      it = first;
    }
  }
  int iterations = 0;
  while (!ret.converged(it)) {
    if (++iterations > kMaxIterations) {
      failure = not_converged(*this, trial, it);
      return up;
    }
    Vec4 r;
    r << it.r_stress, it.r_yield;
    const Vec4 step = ret.jacobian(it).partialPivLu().solve(-r);
    if (!step.allFinite()) {
      failure = not_converged(*this, trial, it);
      return up;
    }
    // Line search on the squared residual: the first of step, step/2, ... that lowers it and
    // keeps d_lambda >= 0.
    double t = 1.0;
    bool moved = false;
    for (int k = 0; k < kMaxHalvings && !moved; ++k, t *= 0.5) {
      const double d_lambda = it.d_lambda + t * step(3);
      if (d_lambda < 0.0) {
        continue;
      }
      const Iterate next = ret.evaluate(it.eta + t * step.head<3>(), d_lambda);
      if (next.merit() < it.merit() || ret.converged(next)) {
        it = next;
        moved = true;
      }
    }
    if (!moved) {
      failure = not_converged(*this, trial, it);
      return up;
    }
  }
  up.plastic = true;
  up.iterations = iterations;
  up.flow_stress = it.static_flow;
  up.d_eps_p = it.d_lambda;
  up.state.eps_p = old.eps_p + it.d_lambda;
  up.state.stress = it.eta;
  for (int i = 0; i < kinematic.count; ++i) {
    const BackStressTerm& t = kinematic.terms[i];
    up.state.back[i] = (old.back[i] + (t.C * it.d_lambda / it.flow.stress) * it.eta) /
                       (1.0 + t.gamma * it.d_lambda);
    up.state.stress += up.state.back[i];
  }
  const Vec3 d_eps_p = it.d_lambda * it.eq.gradient;
  up.d_plastic_work = 0.5 * (old.stress + up.state.stress).dot(d_eps_p);
  up.d_ezz = through_thickness_increment(E, nu, d_strain, old.stress, up.state.stress);
  if (tangent) {
    // d(eta, d_lambda) = J^-1 (d trial, 0), d trial = C d_strain; stress = (1 + B) eta + the
    // decayed back stresses, so d stress = (1 + B) d eta + (dB eta + d_decayed_sum) d d_lambda.
    Eigen::Matrix<double, 4, 3> rhs = Eigen::Matrix<double, 4, 3>::Zero();
    rhs.topRows<3>() = ret.stiffness();
    const Eigen::Matrix<double, 4, 3> d = ret.jacobian(it).partialPivLu().solve(rhs);
    const Vec3 stress_per_lambda = it.dB * it.eta + it.d_decayed_sum;
    *tangent = (1.0 + it.B) * d.topRows<3>() + stress_per_lambda * d.row(3);
  }
  return up;
}

void check_general_plasticity(const GeneralPlasticity& law, const char* what) {
  const std::string name(what);
  if (!(law.E > 0.0) || !std::isfinite(law.E) || !(law.nu > -1.0) || !(law.nu < 0.5)) {
    throw InputError(name + ": needs Young's modulus > 0 and -1 < Poisson's ratio < 0.5 (got E = " +
                     std::to_string(law.E) + ", nu = " + std::to_string(law.nu) + ")");
  }
  check_yield_criterion(law.criterion, what);
  check_hardening(law.hardening, what);
  if (law.kinematic.count < 0 || law.kinematic.count > kMaxBackStresses) {
    throw InputError(name + ": at most " + std::to_string(kMaxBackStresses) +
                     " back stresses (got " + std::to_string(law.kinematic.count) + ")");
  }
  for (int i = 0; i < law.kinematic.count; ++i) {
    const BackStressTerm& t = law.kinematic.terms[i];
    if (!(t.C >= 0.0) || !(t.gamma >= 0.0) || !std::isfinite(t.C) || !std::isfinite(t.gamma)) {
      throw InputError(name + ": back stress " + std::to_string(i + 1) +
                       " needs C >= 0 and gamma >= 0, finite (got C = " + std::to_string(t.C) +
                       ", gamma = " + std::to_string(t.gamma) + ")");
    }
  }
  const CowperSymonds& r = law.rate;
  if (!(r.D >= 0.0) || !std::isfinite(r.D) ||
      (r.active() && (!(r.q > 0.0) || !std::isfinite(r.q)))) {
    throw InputError(name +
                     ": the Cowper-Symonds rate dependence needs D > 0 (1/s) and q > 0, "
                     "finite (got D = " +
                     std::to_string(r.D) + ", q = " + std::to_string(r.q) + ")");
  }
}

}  // namespace sf
