#include "model/physical_ranges.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "material/plane_stress.hpp"
#include "mesh/mean_edge_length.hpp"

namespace sf {
namespace {

// What one check found: a refusal or a warning, its text without the case file.
struct Finding {
  bool refuse = false;
  std::string message;
};

using Findings = std::vector<Finding>;

std::string interval_text(double lo, double hi) {
  return fmt::format("[{:g}, {:g}]", lo, hi);
}

// An absolute value against a physical range: refused outside what any accepted unit system
// makes physical, warned outside the range in the case's own units.
void check_value(const std::string& key, double value, const std::string& unit,
                 const PhysicalRange& range, const UnitSystem& units, Findings& out) {
  const auto [any_lo, any_hi] = range_in_any_units(range);
  const std::string si = fmt::format("{:g} to {:g} {}", range.lo, range.hi, range.si_unit);
  const auto own = range_in_units(range, units);
  const std::string own_text =
      own ? fmt::format("{} {} in the case's units", interval_text(own->first, own->second), unit)
          : std::string();
  if (!(value >= any_lo && value <= any_hi)) {
    out.push_back({true, fmt::format("{} = {:g} {} cannot be a sheet's {} in any unit system "
                                     "sheetform accepts: expected a number in {}, what {} is in "
                                     "one accepted system or another{}",
                                     key, value, unit, range.what, interval_text(any_lo, any_hi),
                                     si, own ? " (" + own_text + ")" : std::string())});
    return;
  }
  if (own && !(value >= own->first && value <= own->second)) {
    out.push_back({false, fmt::format("{} = {:g} {} is outside {}, a sheet's {} ({}); check the "
                                      "value and `units`",
                                      key, value, unit, own_text, range.what, si)});
  }
}

// A dimensionless ratio: refused outside [refuse_lo, refuse_hi], warned outside [warn_lo,
// warn_hi]. `what` says what the ratio is ("blank.thickness / the blank's size").
struct RatioBounds {
  double refuse_lo, warn_lo, warn_hi, refuse_hi;
};

// "at most 1", "at least 1e-06", "in [1e-06, 1]".
std::string bounds_text(double lo, double hi) {
  if (!(lo > 0.0)) {
    return fmt::format("at most {:g}", hi);
  }
  if (std::isinf(hi)) {
    return fmt::format("at least {:g}", lo);
  }
  return "in " + interval_text(lo, hi);
}

void check_ratio(const std::string& subject, const std::string& what, double ratio,
                 const RatioBounds& b, const std::string& why, Findings& out) {
  if (!(ratio >= b.refuse_lo && ratio <= b.refuse_hi)) {
    out.push_back(
        {true, fmt::format("{}: {} is {:.3g}, which no sheet can have ({}): expected "
                           "{} (a warning when not {})",
                           subject, what, ratio, why, bounds_text(b.refuse_lo, b.refuse_hi),
                           bounds_text(b.warn_lo, b.warn_hi))});
  } else if (!(ratio >= b.warn_lo && ratio <= b.warn_hi)) {
    out.push_back({false, fmt::format("{}: {} is {:.3g}, not {} as usual ({})", subject, what,
                                      ratio, bounds_text(b.warn_lo, b.warn_hi), why)});
  }
}

// The flow stress at 0.2 % plastic strain (the proof stress of a tensile test), or -1 for an
// elastic material.
double proof_stress(const Material& material) {
  return std::visit(
      [](const auto& law) -> double {
        if constexpr (requires { law.hardening; }) {
          return flow_stress(law.hardening, 0.002);
        } else {
          return -1.0;
        }
      },
      material);
}

// The blank's part `index` (its material and the wave speed at its density).
void check_material(const CaseConfig& config, const Model& model, std::size_t index,
                    const UnitSystem& u, Findings& out) {
  const ShellMaterial& shell = model.blank.part.materials[index];
  const MaterialConfig& m = config.material_named(config.blank_parts()[index].material);
  const std::string key = "materials." + m.name;
  check_value(key + ".young", m.young, u.stress, kYoungRange, u, out);
  const bool explicit_run = !model.analysis.is_static();
  if (explicit_run) {  // a static analysis does not use the density
    check_value(key + ".density", m.density, u.density(), kDensityRange, u, out);
    const double c = material_wave_speed(shell);
    check_value(key + "'s wave speed sqrt(young / (density (1 - poisson^2)))", c, u.velocity(),
                kWaveSpeedRange, u, out);
  }
  const double yield = proof_stress(shell.law);
  if (yield > 0.0) {
    check_value(key + ".hardening's yield stress at 0.2 % plastic strain", yield, u.stress,
                kYieldRange, u, out);
    check_ratio(key, "the yield strain (yield stress at 0.2 % plastic strain / young)",
                yield / m.young, {1e-6, 1e-4, 0.05, 1.0},
                "metals 1e-4 to 2e-2, polymers up to 5e-2", out);
  }
}

// The blank's size (the diagonal of its nodes' bounding box) and its mean element edge.
struct BlankSize {
  double diagonal = 0.0;
  double mean_edge = 0.0;
};

BlankSize measure_blank(const PartMesh& mesh) {
  BlankSize size;
  if (mesh.nodes.cols() == 0) {
    return size;
  }
  size.diagonal = (mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff()).norm();
  size.mean_edge = mean_edge_length(mesh.nodes, mesh.quads, mesh.triangles);
  return size;
}

void check_blank(const CaseConfig& config, const Model& model, const UnitSystem& u, Findings& out) {
  for (std::size_t i = 0; i < config.blank.parts.size(); ++i) {
    check_value(fmt::format("blank.parts[{}].thickness", i), config.blank.parts[i].thickness,
                u.length, kThicknessRange, u, out);
  }
  const double t = config.largest_blank_thickness();
  if (config.blank.parts.empty()) {
    check_value("blank.thickness", t, u.length, kThicknessRange, u, out);
  }
  if (config.blank.mesh.element_size > 0.0) {
    check_value("blank.element_size", config.blank.mesh.element_size, u.length, kElementSizeRange,
                u, out);
  }
  const BlankSize size = measure_blank(model.blank.mesh);
  if (size.diagonal > 0.0) {
    check_ratio(fmt::format("blank.thickness = {:g} {}", t, u.length),
                fmt::format("its ratio to the blank's size (the diagonal of its bounding box, "
                            "{:g} {})",
                            size.diagonal, u.length),
                t / size.diagonal, {0.0, 0.0, 0.25, 1.0}, "a shell is thinner than it is wide",
                out);
  }
  if (size.mean_edge > 0.0) {
    check_ratio(fmt::format("blank.thickness = {:g} {}", t, u.length),
                fmt::format("its ratio to the blank's mean element edge ({:g} {})", size.mean_edge,
                            u.length),
                t / size.mean_edge, {0.0, 0.0, 10.0, std::numeric_limits<double>::infinity()},
                "shell elements are usually wider than thick; a finer mesh than 1/10 of the "
                "thickness resolves nothing a shell can represent",
                out);
  }
}

// The fastest a tool's prescribed motion goes (length / time): the largest velocity of a
// velocity curve, the steepest slope of a displacement curve.
double peak_speed(const MotionConfig& motion) {
  const CurveConfig& c = motion.curve;
  double peak = 0.0;
  for (std::size_t i = 0; i < c.values.size(); ++i) {
    if (motion.type == MotionConfig::Type::velocity) {
      peak = std::max(peak, std::abs(c.values[i]));
    } else if (motion.type == MotionConfig::Type::displacement && i > 0 &&
               c.times[i] > c.times[i - 1]) {
      peak =
          std::max(peak, std::abs(c.values[i] - c.values[i - 1]) / (c.times[i] - c.times[i - 1]));
    }
  }
  return peak;
}

void check_tool_speeds(const CaseConfig& config, const Model& model, const UnitSystem& u,
                       Findings& out) {
  double c = std::numeric_limits<double>::infinity();  // the slowest part's
  for (const ShellMaterial& m : model.blank.part.materials) {
    c = std::min(c, material_wave_speed(m));
  }
  for (std::size_t i = 0; i < config.tools.size(); ++i) {
    const ToolConfig& tool = config.tools[i];
    if (tool.motion.type != MotionConfig::Type::velocity &&
        tool.motion.type != MotionConfig::Type::displacement) {
      continue;
    }
    const double v = peak_speed(tool.motion);
    check_ratio(fmt::format("tools[{}].motion.curve ('{}'): a peak speed of {:g} {}", i, tool.name,
                            v, u.velocity()),
                fmt::format("its ratio to the sheet's wave speed ({:g} {})", c, u.velocity()),
                v / c, {0.0, 0.0, 0.01, 1.0},
                "no press outruns the sheet's sound waves; forming runs below 1 % of them", out);
  }
}

}  // namespace

std::optional<std::pair<double, double>> range_in_units(const PhysicalRange& range,
                                                        const UnitSystem& units) {
  if (!units.named()) {
    return std::nullopt;
  }
  const double size = units.si_size(range.dimension);
  return std::make_pair(range.lo / size, range.hi / size);
}

std::pair<double, double> range_in_any_units(const PhysicalRange& range) {
  double smallest = std::numeric_limits<double>::infinity();
  double largest = 0.0;
  for (const UnitSystem& units : accepted_unit_systems()) {
    const double size = units.si_size(range.dimension);
    smallest = std::min(smallest, size);
    largest = std::max(largest, size);
  }
  return {range.lo / largest, range.hi / smallest};
}

void check_physical_ranges(const CaseConfig& config, const Model& model) {
  const UnitSystem units = parse_unit_system(config.units);
  Findings findings;
  const std::vector<BlankPartConfig> parts = config.blank_parts();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const bool first_use =
        std::none_of(parts.begin(), parts.begin() + static_cast<long>(i),
                     [&](const auto& p) { return p.material == parts[i].material; });
    if (first_use) {  // each material once
      check_material(config, model, i, units, findings);
    }
  }
  check_blank(config, model, units, findings);
  if (!model.analysis.is_static()) {
    check_tool_speeds(config, model, units, findings);
  }
  const std::string file = config.file.string();
  for (const Finding& f : findings) {
    if (f.refuse) {
      throw InputError(
          fmt::format("{}: {} (docs/case-file.md, \"Physical ranges\")", file, f.message));
    }
  }
  for (const Finding& f : findings) {
    log_warning("{}: {} (docs/case-file.md, \"Physical ranges\")\n", file, f.message);
  }
}

}  // namespace sf
