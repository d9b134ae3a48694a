#include "solver/run_estimate.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "model/blank_parts.hpp"
#include "solver/start_gaps.hpp"

namespace sf {

namespace {

constexpr double kBaseMemory = 100e6;             // bytes: libraries and gmsh
constexpr double kMemoryPerElement = 6e3;         // bytes per blank element
constexpr double kMemoryPerToolTriangle = 0.5e3;  // bytes per tool triangle

// Bytes of one frame: per blank node the coordinates, displacement, velocity and contact force
// (and the springback displacement), per element thickness, plastic strain, the added mass and
// three stress layers, per tool node its coordinates and displacement.
double frame_bytes(const Model& model) {
  const double nodes = static_cast<double>(model.blank.mesh.nodes.cols());
  const double elements = static_cast<double>(element_count(model.blank.part));
  const double node_values = 12.0 + (model.springback ? 3.0 : 0.0);
  const double element_values = 3.0 + (model.output.stress_layers ? 18.0 : 0.0);
  double tool_nodes = 0.0;
  for (const Tool& t : model.tools) {
    tool_nodes += static_cast<double>(t.mesh.nodes.cols());
  }
  return 8.0 * (nodes * node_values + elements * element_values + tool_nodes * 6.0);
}

InitialPenetration find_penetration(const Model& model, const ContactInterface& contact) {
  InitialPenetration p;
  const Tool& tool = model.tools[static_cast<std::size_t>(contact.tool)];
  p.tool = tool.name;
  const VectorX h = initial_half_thickness(model.blank, model.initial);  // mm per node
  const VectorX gaps = start_gaps(model, contact);
  const Matrix3X& x = model.blank.mesh.nodes;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const double depth = std::isnan(gaps[i]) ? 0.0 : -gaps[i];
    // Below a millionth of the thickness is the round-off of a blank resting on a tool.
    if (depth > 2e-6 * h[i]) {
      ++p.nodes;
      if (depth > p.depth) {
        p.depth = depth;
        p.deepest_node = static_cast<int>(i);
        p.position = x.col(i);
        p.thickness = 2.0 * h[i];
      }
    }
  }
  return p;
}

double machine_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page)
                               : std::numeric_limits<double>::infinity();
}

}  // namespace

RunEstimate estimate_run(const CaseConfig& config, const Model& model) {
  RunEstimate e;
  e.elements = element_count(model.blank.part);
  for (const Tool& t : model.tools) {
    e.tool_triangles += static_cast<long>(t.mesh.triangles.cols());
  }
  const bool explicit_run = !model.analysis.is_static();
  // A step of 0 gives an infinite count, which the limit refuses (not 0 cycles, which it passes).
  e.cycles = explicit_run ? model.time.end_time / model.time.time_step : 0.0;
  e.end_time = model.time.end_time;
  e.time_step = model.time.time_step;
  e.element_cycles = e.cycles * static_cast<double>(e.elements);
  e.memory_bytes = kBaseMemory + kMemoryPerElement * static_cast<double>(e.elements) +
                   kMemoryPerToolTriangle * static_cast<double>(e.tool_triangles);
  e.frames = config.control.output_frames;
  const double history_rows =
      e.cycles / std::max(model.output.history_interval, 1) + e.frames + 2.0;
  e.output_bytes = (e.frames + 1.0) * frame_bytes(model) + history_rows * 8.0 * 64.0;
  if (explicit_run) {
    for (const ContactInterface& contact : model.contacts) {
      e.penetrations.push_back(find_penetration(model, contact));
    }
  }
  return e;
}

void print_run_estimate(const RunEstimate& e, const Model& model) {
  if (e.cycles > 0.0) {
    log_info("Cost        about {:.3g} cycles x {} elements = {:.3g} element-cycles\n", e.cycles,
             e.elements, e.element_cycles);
  }
  log_info("Memory      about {:.0f} MB; output about {:.0f} MB ({} frame{} after the first)\n",
           e.memory_bytes / 1e6, e.output_bytes / 1e6, e.frames, e.frames == 1 ? "" : "s");
  for (const InitialPenetration& p : e.penetrations) {
    if (p.nodes == 0) {
      log_info("Start       '{}' does not penetrate the blank\n", p.tool);
      continue;
    }
    log_info(
        "Start       '{}' penetrates the blank at {} node{}: deepest node {} at ({:.4g}, {:.4g}, "
        "{:.4g}) by {:.4g} mm ({:.1f} % of the thickness)\n",
        p.tool, p.nodes, p.nodes == 1 ? "" : "s", p.deepest_node, p.position.x(), p.position.y(),
        p.position.z(), p.depth, 100.0 * p.depth / p.thickness);
  }
}

void enforce_run_limits(const CaseConfig& config, const RunEstimate& e) {
  const LimitsConfig& l = config.limits;
  const std::string file = config.file.string();
  auto refuse = [&](const std::string& what, const std::string& key, const std::string& advice) {
    throw InputError(
        fmt::format("{}: {}, more than limits.{}; {}, or raise limits.{} (docs/"
                    "case-file.md, [limits])",
                    file, what, key, advice, key));
  };
  if (!(e.cycles <= l.max_cycles)) {  // an infinite or NaN count too
    const ControlConfig& c = config.control;
    refuse(
        fmt::format("the run needs about {:.3g} cycles (end time {:.4g} s{} / time step {:.4g} "
                    "s)",
                    e.cycles, e.end_time,
                    c.stroke > 0.0 ? fmt::format(", the time of control.stroke = {:g} mm", c.stroke)
                                   : std::string(" from control.end_time"),
                    e.time_step),
        fmt::format("max_cycles = {:.3g}", l.max_cycles),
        "check the density, the element size and the end time or stroke");
  }
  if (static_cast<double>(e.elements) > l.max_elements) {
    refuse(fmt::format("the blank has {} elements", e.elements),
           fmt::format("max_elements = {:.3g}", l.max_elements), "give a larger element_size");
  }
  if (e.frames > l.max_frames) {
    refuse(fmt::format("control.output_frames = {}", e.frames),
           fmt::format("max_frames = {}", l.max_frames), "ask for fewer frames");
  }
  if (e.output_bytes > l.max_output_gb * 1e9) {
    refuse(fmt::format("the results would take about {:.3g} GB", e.output_bytes / 1e9),
           fmt::format("max_output_gb = {:g}", l.max_output_gb),
           "ask for fewer frames or set output.stress_layers = false");
  }
  const double memory_limit =
      l.max_memory_gb > 0.0 ? l.max_memory_gb * 1e9 : machine_memory_bytes();
  if (e.memory_bytes > memory_limit) {
    refuse(fmt::format("the run needs about {:.3g} GB of memory", e.memory_bytes / 1e9),
           fmt::format("max_memory_gb = {:.3g}{}", memory_limit / 1e9,
                       l.max_memory_gb > 0.0 ? "" : " (this machine's memory)"),
           "give a larger element_size");
  }
  for (const InitialPenetration& p : e.penetrations) {
    const double limit = l.max_initial_penetration * p.thickness;
    if (p.nodes > 0 && p.depth > limit) {
      refuse(
          fmt::format("tool '{}' penetrates the blank at the start at {} nodes, node {} at "
                      "({:.4g}, {:.4g}, {:.4g}) by {:.4g} mm ({:.1f} % of the thickness)",
                      p.tool, p.nodes, p.deepest_node, p.position.x(), p.position.y(),
                      p.position.z(), p.depth, 100.0 * p.depth / p.thickness),
          fmt::format("max_initial_penetration = {:g} of the thickness", l.max_initial_penetration),
          "move the tool clear of the blank (its position, or the blank's offset)");
    }
  }
}

}  // namespace sf
