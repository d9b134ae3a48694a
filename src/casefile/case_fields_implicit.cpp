// The field tables of implicit statics: [analysis], [implicit], [springback] and
// [springback.u_channel] (docs/static-analysis.md).
#include <fmt/core.h>

#include <cmath>

#include "casefile/case_fields.hpp"

namespace sf {

namespace {

// An array [lo, hi] of two finite numbers with lo < hi (mm); required.
void read_range(const TomlSection& s, std::string_view key, std::array<double, 2>& range) {
  const toml::node* node = s.find(key);
  if (!node) {
    s.fail_missing(key, "[lo, hi] in mm");
  }
  const toml::array* array = node->as_array();
  if (!array || array->size() != 2) {
    s.fail_value(key, "an array [lo, hi] of 2 numbers (mm)");
  }
  for (std::size_t i = 0; i < 2; ++i) {
    const std::optional<double> v = number_of(*array->get(i));
    if (!v || !std::isfinite(*v)) {
      s.fail_value(key, "an array [lo, hi] of 2 finite numbers (mm)");
    }
    range[i] = *v;
  }
  if (!(range[0] < range[1])) {
    s.fail_value(key, "[lo, hi] with lo < hi (mm)");
  }
}

Field<UChannelMeasureConfig> range_field(std::string key,
                                         std::array<double, 2> UChannelMeasureConfig::*m,
                                         std::string doc) {
  return custom_field<UChannelMeasureConfig>(
             {key, "array of 2 floats", "required", "mm", "`[lo, hi]`, lo < hi; " + doc},
             [key, m](const TomlSection& s, UChannelMeasureConfig& u, Presence) {
               read_range(s, key, u.*m);
             },
             [key, m](TomlWriter& w, const UChannelMeasureConfig& u) {
               w.raw(key, fmt::format("[{}, {}]", format_toml_number((u.*m)[0]),
                                      format_toml_number((u.*m)[1])));
             })
      .required();
}

FieldTable<AnalysisConfig> make_analysis_fields() {
  using A = AnalysisConfig;
  static constexpr std::array<Choice<A::Type>, 2> kTypes{{
      {A::Type::explicit_dynamic, "explicit", "an explicit forming run"},
      {A::Type::static_equilibrium, "static", "a static analysis of the blank"},
  }};
  static constexpr std::array<Choice<bool>, 2> kGeometry{{
      {true, "linear",
       "one linear solve on the initial geometry (small displacements, the elastic tangent)"},
      {false, "nonlinear", "Newton-Raphson with large rotations and plasticity"},
  }};
  FieldTable<A> t;
  t.push_back(choice_field<A, A::Type>("type", &A::type, kTypes, ""));
  t.push_back(choice_field<A, bool>("geometry", &A::linear, kGeometry, "")
                  .when([](const A& a) { return a.type == A::Type::static_equilibrium; },
                        "`type = \"static\"` only",
                        "it belongs to a static analysis (type = \"static\")"));
  return t;
}

FieldTable<ImplicitConfig> make_implicit_fields() {
  using I = ImplicitConfig;
  static constexpr std::array<Choice<I::LinearSolver>, 3> kSolvers{{
      {I::LinearSolver::automatic, "auto",
       "CHOLMOD when the tangent is symmetric and positive definite, else UMFPACK"},
      {I::LinearSolver::cholmod, "cholmod", ""},
      {I::LinearSolver::umfpack, "umfpack", ""},
  }};
  static constexpr std::array<Choice<I::RigidBodyModes>, 2> kModes{{
      {I::RigidBodyModes::automatic, "auto",
       "hold a minimal set of degrees of freedom that removes the rigid-body modes the "
       "constraints leave free (logged)"},
      {I::RigidBodyModes::error, "error", "stop and name them"},
  }};
  FieldTable<I> t;
  t.push_back(integer_field<I>("increments", &I::increments, IntegerRange{.lo = 1, .hi = 100000},
                               "equal increments the load is applied in; one that fails is "
                               "halved"));
  t.push_back(integer_field<I>("max_iterations", &I::max_iterations,
                               IntegerRange{.lo = 1, .hi = 1000},
                               "Newton iterations per increment before it is cut"));
  t.push_back(integer_field<I>("max_cuts", &I::max_cuts, IntegerRange{.lo = 0, .hi = 30},
                               "successive halvings of one increment before the step stops"));
  t.push_back(number_field<I>("force_tolerance", &I::force_tolerance,
                              interval(0.0, true, 1.0, true),
                              "converged when the residual force norm <= this x the reference "
                              "force norm ..."));
  t.push_back(number_field<I>("displacement_tolerance", &I::displacement_tolerance,
                              interval(0.0, true, 1.0, true),
                              "... and the last correction's norm <= this x the increment's "
                              "displacement norm"));
  t.push_back(bool_field<I>("line_search", &I::line_search,
                            "scale the Newton correction so that it lowers the residual"));
  t.push_back(choice_field<I, I::LinearSolver>("linear_solver", &I::linear_solver, kSolvers, ""));
  t.push_back(
      choice_field<I, I::RigidBodyModes>("rigid_body_modes", &I::rigid_body_modes, kModes, ""));
  return t;
}

FieldTable<SpringbackConfig> make_springback_fields() {
  using S = SpringbackConfig;
  static constexpr std::array<Choice<S::Method>, 2> kMethods{{
      {S::Method::implicit, "implicit",
       "a static Newton step (the [implicit] controls) that releases the tool forces"},
      {S::Method::dynamic_relaxation, "dynamic_relaxation",
       "the tool forces ramped to zero over release_time, then kinetic damping until the blank "
       "is at rest"},
  }};
  const auto relaxation = [](const S& s) { return s.method == S::Method::dynamic_relaxation; };
  const std::string relaxation_only =
      "it belongs to method = \"dynamic_relaxation\" (the implicit method takes its controls "
      "from [implicit])";
  FieldTable<S> t;
  t.push_back(choice_field<S, S::Method>("method", &S::method, kMethods, ""));
  t.push_back(number_field<S>("release_time", &S::release_time, greater_than(0.0, "s"))
                  .required()
                  .when(relaxation, "`dynamic_relaxation` only", relaxation_only));
  Field<S> max_time = number_field<S>("max_time", &S::max_time, at_least(0.0, "s"),
                                      "the longest the relaxation may run after the release; "
                                      "0 = 10 x release_time")
                          .when(relaxation, "`dynamic_relaxation` only", relaxation_only);
  max_time.read = [](const TomlSection& s, S& sb, Presence) {
    s.read_number("max_time", sb.max_time, at_least(0.0, "s"));
    if (sb.max_time == 0.0) {
      sb.max_time = 10.0 * sb.release_time;
    }
  };
  t.push_back(std::move(max_time));
  t.push_back(number_field<S>("kinetic_tolerance", &S::kinetic_tolerance,
                              interval(0.0, true, 1.0, true),
                              "at rest when the kinetic energy is below this x the internal "
                              "energy")
                  .when(relaxation, "`dynamic_relaxation` only", relaxation_only));
  t.push_back(number_field<S>("stabilization", &S::stabilization, interval(0.0, false, 1e-2, false),
                              "stabilising springs on every node's translations, this x E x the "
                              "mean thickness (N/mm), removed at the end of each increment "
                              "(docs/static-analysis.md)")
                  .when([](const S& s) { return s.method == S::Method::implicit; },
                        "`implicit` only",
                        "it belongs to method = \"implicit\" (dynamic relaxation releases the "
                        "tool forces over release_time instead)"));
  return t;
}

FieldTable<UChannelMeasureConfig> make_u_channel_fields() {
  using U = UChannelMeasureConfig;
  FieldTable<U> t;
  t.push_back(string_field<U>("section", &U::section, "node group: a line of blank nodes along x")
                  .required());
  t.push_back(range_field("bottom", &U::bottom, "x range of the bottom (formed shape)"));
  t.push_back(range_field("wall", &U::wall, "z range of the side wall (formed shape)"));
  t.push_back(range_field("flange", &U::flange, "x range of the flange (formed shape)"));
  return t;
}

}  // namespace

const FieldTable<AnalysisConfig>& analysis_fields() {
  static const FieldTable<AnalysisConfig> table = make_analysis_fields();
  return table;
}

const FieldTable<ImplicitConfig>& implicit_fields() {
  static const FieldTable<ImplicitConfig> table = make_implicit_fields();
  return table;
}

const FieldTable<SpringbackConfig>& springback_fields() {
  static const FieldTable<SpringbackConfig> table = make_springback_fields();
  return table;
}

const FieldTable<UChannelMeasureConfig>& u_channel_fields() {
  static const FieldTable<UChannelMeasureConfig> table = make_u_channel_fields();
  return table;
}

}  // namespace sf
