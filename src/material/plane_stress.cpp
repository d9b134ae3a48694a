#include "material/plane_stress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "core/errors.hpp"
#include "material/plane_stress_batch.hpp"

namespace sf {

namespace {

// One point's update through the batched kernels, a failure thrown as an InstabilityError.
template <class Kernel>
PlaneStressUpdate update_one_point(const Kernel& kernel, const PlaneStressState& old,
                                   const Vec3& d_strain) {
  PlaneStressUpdate up;
  MaterialFailure failure;
  if (!update_points(kernel, 1, &old.stress, &old.eps_p, &d_strain, FlowStressCache{}, &up,
                     failure)) {
    throw_if_failed(failure);
  }
  return up;
}

}  // namespace

Mat3 plane_stress_stiffness(double E, double nu) {
  const double f = E / (1.0 - nu * nu);
  Mat3 c;
  c << f, f * nu, 0.0, f * nu, f, 0.0, 0.0, 0.0, 0.5 * f * (1.0 - nu);
  return c;
}

double von_mises_plane_stress(const Vec3& s) {
  return std::sqrt(s(0) * s(0) - s(0) * s(1) + s(1) * s(1) + 3.0 * s(2) * s(2));
}

double plane_stress_wave_speed(double E, double nu, double rho) {
  return std::sqrt(E / (rho * (1.0 - nu * nu)));
}

PlaneStressUpdate ElasticPlaneStress::update(const State& old, const Vec3& d_strain) const {
  return update_one_point(ElasticKernel(*this), old, d_strain);
}

// The single-point update is a batch of one (plane_stress_batch.hpp): the element loops' batched
// update gives the same bits.
PlaneStressUpdate J2PlaneStress::update(const State& old, const Vec3& d_strain) const {
  return update_one_point(J2Kernel(*this), old, d_strain);
}

Hill48Coefficients hill48_coefficients(double r0, double r45, double r90) {
  const double G = 1.0 / (1.0 + r0);
  const double H = r0 / (1.0 + r0);
  const double F = r0 / (r90 * (1.0 + r0));
  const double N = (r0 + r90) * (1.0 + 2.0 * r45) / (2.0 * r90 * (1.0 + r0));
  return {F, G, H, N};
}

double hill48_equivalent_stress(const Hill48Coefficients& c, const Vec3& s) {
  const double d = s(0) - s(1);
  return std::sqrt(c.G * s(0) * s(0) + c.F * s(1) * s(1) + c.H * d * d + 2.0 * c.N * s(2) * s(2));
}

PlaneStressUpdate Hill48PlaneStress::update(const State& old, const Vec3& d_strain) const {
  return update_one_point(Hill48Kernel(*this), old, d_strain);
}

Vec3 rotate_strain(const Vec3& e, double angle) {
  return rotate_strain(e, std::cos(angle), std::sin(angle));
}

Vec3 rotate_stress(const Vec3& t, double angle) {
  return rotate_stress(t, std::cos(angle), std::sin(angle));
}

double young_modulus(const Material& material) {
  return std::visit([](const auto& m) { return m.E; }, material);
}

double poisson_ratio(const Material& material) {
  return std::visit([](const auto& m) { return m.nu; }, material);
}

void check_material(const Material& material, const char* what) {
  if (const auto* g = std::get_if<GeneralPlasticity>(&material)) {
    check_general_plasticity(*g, what);  // its elasticity too
    return;
  }
  const double E = young_modulus(material);
  const double nu = poisson_ratio(material);
  if (!(E > 0.0) || !std::isfinite(E) || !(nu > -1.0) || !(nu < 0.5)) {
    throw InputError(std::string(what) +
                     ": needs Young's modulus > 0 and -1 < Poisson's ratio < 0.5 (got E = " +
                     std::to_string(E) + ", nu = " + std::to_string(nu) + ")");
  }
  if (const auto* j2 = std::get_if<J2PlaneStress>(&material)) {
    check_hardening(j2->hardening, what);
  }
  if (const auto* h = std::get_if<Hill48PlaneStress>(&material)) {
    for (const double r : {h->r0, h->r45, h->r90}) {
      if (!(r > 0.0) || !std::isfinite(r)) {
        throw InputError(std::string(what) + ": Hill48 needs r0, r45, r90 > 0 (got " +
                         std::to_string(h->r0) + ", " + std::to_string(h->r45) + ", " +
                         std::to_string(h->r90) + ")");
      }
    }
    check_hardening(h->hardening, what);
  }
}

}  // namespace sf
