// The element pass's bits as one hash, printed (issue 34, item 6): the batched kernels (the
// modal return, material/modal_return_batch.cpp, and the quad geometry blocks,
// element/shell_geometry_batch.cpp) are compiled for generic x86-64 and for x86-64-v3, the variant
// chosen at run time by the processor. This program is built twice (tests/CMakeLists.txt): as the
// solver is, and with those two files built for generic x86-64 only (SF_NO_MULTIVERSIONING).
// ctest's simd_generic_path runs both and requires the same hash, so that the variant this machine
// does not choose is run and the two cannot drift apart.
//
// What is hashed: three steps of a stretching, bending and twisting velocity field that yields,
// on a warped and distorted mixed mesh of quads and triangles, for both formulations and four
// laws (J2 with Swift and with linear hardening, Hill48 with Swift at a material angle, elastic):
// the corner forces, the element state, the critical steps and the works.
// Prints "<hash> <variant>", the variant the processor chose for this build.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "element/shell_directors.hpp"
#include "element/shell_forces.hpp"
#include "support/warped_mixed_mesh.hpp"

namespace {

using namespace sf;

// FNV-1a over bytes.
struct Hash {
  std::uint64_t value = 14695981039346656037ull;
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k) {
      value = (value ^ p[k]) * 1099511628211ull;
    }
  }
  void add(const std::vector<double>& a) { add(a.data(), a.size() * sizeof(double)); }
  void add(double a) { add(&a, sizeof a); }
};

ShellMaterial material(int which) {
  const SwiftHardening swift{565.0, 0.007, 0.26};
  switch (which) {
    case 0:
      return {J2PlaneStress{210000.0, 0.3, swift}, 7.85e-9};
    case 1:
      return {J2PlaneStress{210000.0, 0.3, LinearHardening{200.0, 1000.0}}, 7.85e-9};
    case 2:
      return {Hill48PlaneStress{210000.0, 0.3, 1.79, 1.51, 2.27, swift}, 7.85e-9};
    default:
      return {ElasticPlaneStress{210000.0, 0.3}, 7.85e-9};
  }
}

void hash_passes(ShellFormulation formulation, int law, Hash& hash) {
  const test::Mesh mesh = test::make_mesh(24, 14, 5);
  ShellPart part = test::make_part(mesh, formulation);
  part.materials[0] = material(law);
  if (law == 2) {
    part.material_angle.assign(static_cast<std::size_t>(element_count(part)), 0.5);  // rad
  }
  ShellState st = make_shell_state(element_count(part), 5, 0.8);
  initialize_directors(part, mesh.x, st);
  Matrix3X x = mesh.x;
  Matrix3X v;
  Matrix3X w;
  test::yielding_motion(mesh.x, v, w);
  const double dt = 1e-6;  // s
  ElementPass pass;
  std::vector<double> element_dt(static_cast<std::size_t>(element_count(part)), 0.0);
  for (int step = 0; step < 3; ++step) {
    x += dt * v;
    const ShellForceResult works =
        run_element_pass(part, ElementInputs{x, v, w, dt}, st, pass, element_dt);
    hash.add(works.internal_work);
    hash.add(works.plastic_work);
    hash.add(works.hourglass_work);
  }
  hash.add(pass.corners);
  hash.add(element_dt);
  for (const std::vector<double>* a : {&st.sxx, &st.syy, &st.sxy, &st.eps_p, &st.thickness, &st.sxz,
                                       &st.syz, &st.hourglass, &st.director}) {
    hash.add(*a);
  }
}

const char* chosen_variant() {
#if defined(SF_NO_MULTIVERSIONING)
  return "generic (built so)";
#elif defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v3") ? "x86-64-v3 (chosen at run time)"
                                             : "generic (chosen at run time: no x86-64-v3)";
#else
  return "generic (no multiversioning in this compiler)";
#endif
}

}  // namespace

int main() {
  Hash hash;
  for (const ShellFormulation f :
       {ShellFormulation::belytschko_tsay, ShellFormulation::assumed_strain}) {
    for (int law = 0; law < 4; ++law) {
      hash_passes(f, law, hash);
    }
  }
  std::printf("%016llx %s\n", static_cast<unsigned long long>(hash.value), chosen_variant());
  return 0;
}
