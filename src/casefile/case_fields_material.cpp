// The field tables of [materials.NAME] and its [hardening], [kinematic] and [cowper_symonds]
// tables (docs/material.md).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "casefile/case_fields.hpp"

namespace sf {

namespace fs = std::filesystem;

namespace {

using Type = MaterialConfig::Type;
using Law = HardeningConfig::Law;

/// The optional forming limit curve: an array of at least 2 [minor, major] true-strain points,
/// finite, minor strictly increasing, major > 0.
void read_forming_limit_curve(const TomlSection& s, std::vector<std::array<double, 2>>& out) {
  constexpr std::string_view key = "forming_limit_curve";
  const toml::node* node = s.find(key);
  if (!node) {
    return;
  }
  const auto* points = node->as_array();
  if (!points || points->size() < 2) {
    s.fail_value(key, "an array of at least 2 [minor, major] true-strain points");
  }
  std::vector<std::array<double, 2>> curve;
  for (std::size_t i = 0; i < points->size(); ++i) {
    const toml::node& point_node = *points->get(i);
    const std::string point_path = fmt::format("{}[{}]", s.key_path(key), i);
    const auto* point = point_node.as_array();
    std::optional<double> minor, major;
    if (point && point->size() == 2) {
      minor = number_of(*point->get(0));
      major = number_of(*point->get(1));
    }
    if (!minor || !major || !std::isfinite(*minor) || !std::isfinite(*major)) {
      s.fail_at(point_node, point_path,
                fmt::format("expected a point [minor, major] of 2 finite numbers (true strains), "
                            "got {}",
                            describe_value(point_node)));
    }
    if (!(*major > 0.0)) {
      s.fail_at(point_node, point_path,
                fmt::format("expected a major strain > 0, got {}", format_toml_number(*major)));
    }
    if (!curve.empty() && !(*minor > curve.back()[0])) {
      s.fail_at(point_node, point_path,
                fmt::format("expected minor strains strictly increasing, got {} after {}",
                            format_toml_number(*minor), format_toml_number(curve.back()[0])));
    }
    curve.push_back({*minor, *major});
  }
  // A forming limit curve falls to its lowest point (near plane strain) and rises after it.
  const auto lowest = static_cast<std::size_t>(
      std::min_element(curve.begin(), curve.end(),
                       [](const auto& a, const auto& b) { return a[1] < b[1]; }) -
      curve.begin());
  for (std::size_t i = 1; i < curve.size(); ++i) {
    const bool left = i <= lowest;
    if (left ? curve[i][1] > curve[i - 1][1] : curve[i][1] < curve[i - 1][1]) {
      s.fail_at(
          *points->get(i), fmt::format("{}[{}]", s.key_path(key), i),
          fmt::format("expected a curve that falls to its lowest major strain ({} at "
                      "minor {}) and rises after it; major {} at minor {} {} after {}",
                      format_toml_number(curve[lowest][1]), format_toml_number(curve[lowest][0]),
                      format_toml_number(curve[i][1]), format_toml_number(curve[i][0]),
                      left ? "rises" : "falls", format_toml_number(curve[i - 1][1])));
    }
  }
  out = std::move(curve);
}

bool fitted_yld2000(const MaterialConfig& m) {
  return m.type == Type::yld2000 && m.alpha.empty();
}

bool takes_r_values(const MaterialConfig& m) {
  return m.type == Type::hill48 || m.type == Type::yld89 || fitted_yld2000(m);
}

/// Why a Yld2000-2d datum (r-values included) is refused here.
std::string fit_data_refused(const MaterialConfig& m) {
  if (m.type == Type::yld2000) {
    return "alpha is given: Yld2000-2d is not fitted (give either alpha or the eight data)";
  }
  return "Yld2000-2d coefficients and data are for type = \"yld2000\"";
}

std::string r_values_refused(const MaterialConfig& m) {
  if (m.type == Type::yld2000) {
    return fit_data_refused(m);
  }
  return "Lankford coefficients are for type = \"hill48\", \"yld89\" or \"yld2000\"";
}

FieldTable<MaterialConfig> make_material_fields() {
  using M = MaterialConfig;
  const auto barlat = [](const M& m) { return m.type == Type::yld2000 || m.type == Type::yld89; };
  FieldTable<M> t;
  t.push_back(choice_field<M, Type>("type", &M::type, kMaterialTypeNames, ""));
  t.push_back(number_field<M>("density", &M::density, greater_than(0.0, "tonne/mm^3")).required());
  t.push_back(number_field<M>("young", &M::young, greater_than(0.0, "MPa")).required());
  t.push_back(number_field<M>("poisson", &M::poisson, interval(-1.0, true, 0.5, true)).required());
  t.push_back(number_field<M>("exponent", &M::exponent, at_least(2.0),
                              "Barlat's exponent a (M for Yld89); 8 for aluminium (fcc), 6 for "
                              "steel (bcc)")
                  .when(barlat, "`yld2000` and `yld89` only",
                        "the exponent is for type = \"yld2000\" or \"yld89\""));
  t.push_back(numbers_field<M>("alpha", &M::alpha, NumberRange{}, 8, 8,
                               "the coefficients α1..α8 given directly; then the fitting data "
                               "below are not allowed")
                  .when([](const M& m) { return m.type == Type::yld2000; }, "`yld2000` only",
                        "Yld2000-2d coefficients and data are for type = \"yld2000\""));
  const NumberRange stress = greater_than(0.0, "MPa, or ratios");
  const std::pair<const char*, double M::*> stresses[] = {{"sigma0", &M::sigma0},
                                                          {"sigma45", &M::sigma45},
                                                          {"sigma90", &M::sigma90},
                                                          {"sigma_b", &M::sigma_b}};
  for (const auto& [key, member] : stresses) {
    t.push_back(number_field<M>(key, member, stress,
                                "yield stress in uniaxial tension at 0°, 45°, 90° or in "
                                "equibiaxial tension (sigma_b); only ratios to `sigma0` are used")
                    .required()
                    .when(fitted_yld2000, "`yld2000` without `alpha`", fit_data_refused));
  }
  const std::pair<const char*, double M::*> r_values[] = {
      {"r0", &M::r0}, {"r45", &M::r45}, {"r90", &M::r90}};
  for (const auto& [key, member] : r_values) {
    t.push_back(number_field<M>(key, member, greater_than(0.0),
                                "Lankford coefficient (plastic width / thickness strain ratio in "
                                "uniaxial tension) at 0°, 45° or 90° to the rolling direction")
                    .required()
                    .when(takes_r_values, "`hill48`, `yld89`, `yld2000` without `alpha`",
                          r_values_refused));
  }
  t.push_back(number_field<M>("r_b", &M::r_b, greater_than(0.0),
                              "equibiaxial r-value dε_yy / dε_xx (disk compression or bulge "
                              "test; 1 when unknown is the isotropic value)")
                  .required()
                  .when(fitted_yld2000, "`yld2000` without `alpha`", fit_data_refused));
  t.push_back(custom_field<M>(
                  {"forming_limit_curve", "array of `[minor, major]`", "none", "— (true strain)",
                   "any type: the forming limit curve, at least 2 points of finite numbers, "
                   "minor strain strictly increasing, major strain > 0, falling to its lowest "
                   "point and rising after it; the formability results' margin and zones "
                   "(docs/formability.md). None: the Keeler-Brazier curve of a Swift law's n"},
                  [](const TomlSection& s, M& m, Presence) {
                    read_forming_limit_curve(s, m.forming_limit_curve);
                  },
                  [](TomlWriter& w, const M& m) {
                    w.points("forming_limit_curve", m.forming_limit_curve,
                             "[[minor, major], ...] true strains (docs/formability.md)");
                  })
                  .write_if([](const M& m) { return !m.forming_limit_curve.empty(); }));
  return t;
}

FieldTable<HardeningConfig> make_hardening_fields() {
  using H = HardeningConfig;
  const auto law_is = [](std::initializer_list<Law> laws) {
    return [laws = std::vector<Law>(laws)](const H& h) {
      return std::find(laws.begin(), laws.end(), h.law) != laws.end();
    };
  };
  const auto only = [](std::string_view laws) { return fmt::format("{} only", laws); };
  // The keys of h's law, from the table itself (built by the time a message needs them).
  const auto not_here = [](const H& h) {
    std::string keys;
    for (const Field<H>& f : hardening_fields()) {
      if (!f.applies || f.applies(h)) {
        keys += fmt::format("{}{}", keys.empty() ? "" : ", ", f.doc.key);
      }
    }
    return fmt::format("unknown key for law = {}; accepted keys here: {}",
                       quote_toml_string(choice_name<Law>(kHardeningLawNames, h.law)), keys);
  };
  FieldTable<H> t;
  t.push_back(choice_field<H, Law>("law", &H::law, kHardeningLawNames, ""));
  const auto add = [&](Field<H> f, std::initializer_list<Law> laws, std::string_view names,
                       bool required = true) {
    if (required) {
      f = std::move(f).required();
    }
    t.push_back(std::move(f).when(law_is(laws), only(names), not_here));
  };
  add(number_field<H>("K", &H::swift_k, greater_than(0.0, "MPa"), "σy = K (ε0 + εp)ⁿ"),
      {Law::swift, Law::swift_voce}, "swift, swift_voce");
  add(number_field<H>(
          "eps0", &H::swift_eps0,
          [](const H& h) { return h.law == Law::swift ? at_least(0.0) : greater_than(0.0); }, "",
          ">= 0 (swift), > 0 (swift_voce)"),
      {Law::swift, Law::swift_voce}, "swift, swift_voce");
  add(number_field<H>("n", &H::swift_n, interval(0.0, false, 1.0, true)),
      {Law::swift, Law::swift_voce}, "swift, swift_voce");
  add(number_field<H>("yield_stress", &H::yield_stress, greater_than(0.0, "MPa"),
                      "σy = σy0 + H εp"),
      {Law::linear}, "linear");
  add(number_field<H>("modulus", &H::modulus, at_least(0.0, "MPa"), "the plastic modulus H"),
      {Law::linear}, "linear");
  add(number_field<H>("sigma0", &H::voce_sigma0, greater_than(0.0, "MPa"),
                      "initial yield stress; σy = σ0 + Q (1 − exp(−b εp))"),
      {Law::voce, Law::swift_voce}, "voce, swift_voce");
  add(number_field<H>("Q", &H::voce_q, at_least(0.0, "MPa"), "saturation increase (σy → σ0 + Q)"),
      {Law::voce, Law::swift_voce}, "voce, swift_voce");
  add(number_field<H>("b", &H::voce_b, greater_than(0.0), "saturation rate"),
      {Law::voce, Law::swift_voce}, "voce, swift_voce");
  add(number_field<H>("A", &H::ludwik_a, greater_than(0.0, "MPa"),
                      "initial yield stress; σy = A + B εpⁿ (Ludwik; Hollomon with an offset)"),
      {Law::ludwik}, "ludwik");
  add(number_field<H>("B", &H::ludwik_b, at_least(0.0, "MPa")), {Law::ludwik}, "ludwik");
  add(number_field<H>("n", &H::ludwik_n, interval(0.0, true, 1.0, false),
                      "the slope n B εpⁿ⁻¹ is infinite at εp = 0 for n < 1: the return mapping "
                      "handles it"),
      {Law::ludwik}, "ludwik");
  add(number_field<H>("sigma_s", &H::hs_sigma_s, greater_than(0.0, "MPa"),
                      "saturation stress; σy = σs − (σs − σi) exp(−N εp^p) (Hockett & Sherby "
                      "1975)"),
      {Law::hockett_sherby}, "hockett_sherby");
  add(number_field<H>(
          "sigma_i", &H::hs_sigma_i,
          [](const H& h) { return interval(0.0, true, h.hs_sigma_s, false, "MPa"); }, "MPa",
          "0 < σi <= σs", "initial yield stress"),
      {Law::hockett_sherby}, "hockett_sherby");
  add(number_field<H>("N", &H::hs_n, greater_than(0.0)), {Law::hockett_sherby}, "hockett_sherby");
  add(number_field<H>("p", &H::hs_p, interval(0.0, true, 1.0, false), "p = 1: Voce's form"),
      {Law::hockett_sherby}, "hockett_sherby", false);
  add(number_field<H>("weight", &H::sv_weight, interval(0.0, false, 1.0, false),
                      "the Swift part's weight: σy = w K (ε0 + εp)ⁿ + (1 − w)(σ0 + Q (1 − "
                      "exp(−b εp)))"),
      {Law::swift_voce}, "swift_voce");
  add(custom_field<H>(
          {"file",
           "string",
           "required",
           {},
           "a `.csv` file (relative to the case file's folder; stored absolute), "
           "must exist"},
          [](const TomlSection& s, H& h, Presence) {
            h.table_file = read_existing_file(
                s, "file", [](const fs::path& p) { return p.extension() == ".csv"; },
                "a .csv file");
          },
          [](TomlWriter& w, const H& h) { w.string("file", h.table_file.string()); }),
      {Law::tabulated}, "tabulated", false);
  return t;
}

FieldTable<KinematicConfig> make_kinematic_fields() {
  using K = KinematicConfig;
  FieldTable<K> t;
  t.push_back(numbers_field<K>("C", &K::C, at_least(0.0, "MPa"), 1, 4,
                               "each back stress's initial kinematic modulus")
                  .required());
  Field<K> gamma = numbers_field<K>("gamma", &K::gamma, at_least(0.0), 1, 4,
                                    "one per `C`: each back stress's rate of saturation (0: "
                                    "linear Prager)")
                       .required();
  gamma.read = [](const TomlSection& s, K& k, Presence p) {
    s.read_numbers("gamma", k.gamma, at_least(0.0), 1, 4, p);
    if (k.gamma.size() != k.C.size()) {
      s.fail_value("gamma", fmt::format("one gamma per back stress: an array of {} numbers (as C)",
                                        k.C.size()));
    }
  };
  t.push_back(std::move(gamma));
  return t;
}

FieldTable<CowperSymondsConfig> make_cowper_symonds_fields() {
  using C = CowperSymondsConfig;
  FieldTable<C> t;
  t.push_back(number_field<C>("D", &C::D, greater_than(0.0, "1/s"),
                              "the plastic strain rate at which the flow stress doubles")
                  .required());
  t.push_back(number_field<C>("q", &C::q, greater_than(0.0)).required());
  return t;
}

}  // namespace

const FieldTable<MaterialConfig>& material_fields() {
  static const FieldTable<MaterialConfig> table = make_material_fields();
  return table;
}

const FieldTable<HardeningConfig>& hardening_fields() {
  static const FieldTable<HardeningConfig> table = make_hardening_fields();
  return table;
}

const FieldTable<KinematicConfig>& kinematic_fields() {
  static const FieldTable<KinematicConfig> table = make_kinematic_fields();
  return table;
}

const FieldTable<CowperSymondsConfig>& cowper_symonds_fields() {
  static const FieldTable<CowperSymondsConfig> table = make_cowper_symonds_fields();
  return table;
}

}  // namespace sf
