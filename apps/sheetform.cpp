// sheetform: explicit finite-element simulation of sheet metal forming, with springback and
// static analyses by an implicit static step.
//
//   sheetform run   CASE [-o DIR]   run a case, write results (HDF5 + XDMF for ParaView)
//   sheetform check CASE            validate a case and print the model it builds
//   sheetform mesh  CASE [-o DIR]   write only the meshes (HDF5 + XDMF, and .msh of each .geo)
//
// Exit codes: 0 success, 2 bad input, 3 the run went unstable, 4 a static step did not converge
// (or its stiffness is singular), 1 an internal error.
#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "core/log.hpp"
#include "io/case_config.hpp"
#include "io/gmsh_reader.hpp"
#include "model/build_model.hpp"
#include "model/constraint_assembly.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/frame_output.hpp"
#include "solver/static_driver.hpp"

namespace fs = std::filesystem;

namespace {

struct Arguments {
  std::string case_file;
  std::string output_directory;
  double stroke = -1.0;    // mm; < 0 = as in the case
  double end_time = -1.0;  // s; < 0 = as in the case
  std::string search;      // "" = as in the case; else the search of every [[contact]]
  bool quiet = false;
  bool verbose = false;
};

// Command-line overrides of the case's end condition (used for short versions of long runs).
void apply_overrides(const Arguments& args, sf::CaseConfig& config) {
  if (args.stroke >= 0.0 && args.end_time >= 0.0) {
    throw sf::InputError("give --stroke or --end-time, not both");
  }
  if (args.stroke > 0.0) {
    if (config.control.stroke_tool.empty()) {
      throw sf::InputError(config.file.string() + ": --stroke needs a moving tool (none moves)");
    }
    config.control.stroke = args.stroke;
    config.control.end_time = 0.0;
  }
  if (args.end_time > 0.0) {
    config.control.end_time = args.end_time;
    config.control.stroke = 0.0;
  }
  if (!args.search.empty()) {
    if (config.contacts.empty()) {
      throw sf::InputError(config.file.string() +
                           ": --search needs a [[contact]] (the case has none)");
    }
    for (sf::ContactConfig& contact : config.contacts) {
      contact.search = args.search;
      if (args.search != "cached") {
        contact.search_margin = 0.0;  // a cached-search option only
      }
    }
  }
}

fs::path output_directory(const Arguments& args, const sf::CaseConfig& config) {
  if (!args.output_directory.empty()) {
    return fs::absolute(args.output_directory);
  }
  return config.file.parent_path() / config.output.directory;
}

void print_material(const sf::CaseConfig& config) {
  const sf::MaterialConfig& m = config.blank_material();
  using Type = sf::MaterialConfig::Type;
  using Law = sf::HardeningConfig::Law;
  std::string law = "elastic";
  if (m.type == Type::hill48) {
    const auto& d = config.blank.rolling_direction;
    law = fmt::format("Hill48 (r0 {}, r45 {}, r90 {}; rolling direction ({:.3g}, {:.3g}, {:.3g}))",
                      m.r0, m.r45, m.r90, d[0], d[1], d[2]);
  } else if (m.type == Type::von_mises) {
    law = "von Mises";
  }
  if (m.type != Type::elastic) {
    static constexpr const char* names[] = {"Swift", "linear", "Voce", "tabulated"};
    law += fmt::format(", {} hardening", names[static_cast<int>(m.hardening.law)]);
    if (m.hardening.law == Law::tabulated) {
      law += fmt::format(" ({})", m.hardening.table_file.string());
    }
  }
  sf::log_info("Material    '{}': E = {} MPa, nu = {}, {}\n", m.name, m.young, m.poisson, law);
}

void print_model(const sf::Model& model) {
  const sf::Blank& blank = model.blank;
  sf::log_info("Case        {}\n", model.config.file.string());
  if (!model.config.title.empty()) {
    sf::log_info("Title       {}\n", model.config.title);
  }
  sf::log_info("Units       {}\n", model.config.units);
  const sf::BlankConfig& bc = model.config.blank;
  sf::log_info(
      "Blank       {} nodes, {} quadrilateral shells (Belytschko-Lin-Tsay), {} triangular shells "
      "(C0, DSG3), t = {} mm, {} {} thickness points, {} hourglass control {}, material '{}'\n",
      blank.mesh.nodes.cols(), blank.mesh.quads.cols(), blank.mesh.triangles.cols(), bc.thickness,
      bc.integration_points,
      bc.integration_rule == sf::BlankConfig::IntegrationRule::lobatto ? "Lobatto" : "Gauss",
      bc.hourglass_form == sf::BlankConfig::HourglassForm::stiffness ? "stiffness" : "viscous",
      bc.hourglass_coefficient, bc.material);
  print_material(model.config);
  sf::log_info(
      "Mass        {:.6e} tonne physical, {:.6e} tonne added by mass scaling ({:.2f} %, "
      "{} elements)\n",
      blank.physical_mass, blank.scaling.added_mass,
      100.0 * blank.scaling.added_mass / blank.physical_mass, blank.scaling.scaled_elements);
  if (blank.scaling.enabled()) {
    sf::log_info(
        "Mass scale  target step {:.4e} s; elements below it get mass during the run too\n",
        blank.scaling.target_dt);
  }
  for (const sf::BoundaryConfig& b : model.config.boundaries) {
    sf::log_info("Boundary    '{}': {} nodes, {}\n", b.group, blank.group(b.group).nodes.size(),
                 sf::describe_boundary(b));
  }
  for (const sf::PrescribedMotion& p : model.prescribed_motions) {
    sf::log_info("Prescribed  '{}': {} nodes, {} {} along ({:.3g}, {:.3g}, {:.3g}) ({})\n", p.group,
                 p.nodes.size(), p.rotation ? "rotation" : "translation",
                 p.kind == sf::PrescribedMotion::Kind::displacement ? "displacement" : "velocity",
                 p.direction.x(), p.direction.y(), p.direction.z(), p.entry);
  }
  if (model.constraints.frames.count() > 0) {
    const int framed = model.constraints.frames.count();
    sf::log_info("Node axes   {} node{} in axes of {} own (from the constraints there)\n", framed,
                 framed == 1 ? "" : "s", framed == 1 ? "its" : "their");
  }
  for (std::size_t i = 0; i < model.tools.size(); ++i) {
    const sf::Tool& t = model.tools[i];
    std::string motion = "fixed";
    if (t.force_control) {
      // Its frequency on the contact springs of its pair, against the bound build_model checks.
      double k_sum = 0.0;
      for (const sf::ContactInterface& c : model.contacts) {
        if (c.tool == static_cast<int>(i)) {
          k_sum += c.pair.stiffness.sum();
        }
      }
      motion = fmt::format(
          "force-controlled along ({:.3g}, {:.3g}, {:.3g}), mass {:.4e} tonne, damping {} 1/s; "
          "sqrt(sum k / mass) dt = {:.3f}",
          t.direction().x(), t.direction().y(), t.direction().z(), t.force_control->mass(),
          t.force_control->damping(), std::sqrt(k_sum / t.force_control->mass()) * model.time_step);
    } else if (t.motion.moves()) {
      motion = fmt::format("moves along ({:.3g}, {:.3g}, {:.3g})", t.direction().x(),
                           t.direction().y(), t.direction().z());
    }
    sf::log_info("Tool        '{}': {} nodes, {} triangles, {}\n", t.name, t.mesh.nodes.cols(),
                 t.mesh.triangles.cols(), motion);
  }
  for (const sf::ContactInterface& c : model.contacts) {
    const sf::ContactConfig* cc = nullptr;
    for (const auto& candidate : model.config.contacts) {
      if (candidate.tool == model.tools[static_cast<std::size_t>(c.tool)].name) {
        cc = &candidate;
      }
    }
    sf::log_info(
        "Contact     blank nodes vs '{}': search '{}', penalty scale {}, stiffness {:.4g} to "
        "{:.4g} N/mm\n",
        model.tools[static_cast<std::size_t>(c.tool)].name, cc->search, cc->penalty_scale,
        c.pair.stiffness.minCoeff(), c.pair.stiffness.maxCoeff());
  }
  sf::log_info("Time step   {:.4e} s (safety {} x critical, limited by element {})\n",
               model.time_step, model.config.control.time_step_safety, model.limiting_element);
  sf::log_info("End time    {:.6e} s{}\n", model.end_time,
               model.config.control.stroke > 0.0
                   ? fmt::format(" (stroke {} mm of '{}')", model.config.control.stroke,
                                 model.config.control.stroke_tool)
                   : std::string());
  sf::log_info("Cycles      about {:.0f}\n", model.end_time / model.time_step);
}

sf::Model load(const Arguments& args) {
  // 1. Read and validate the case file.
  sf::CaseConfig config = sf::read_case(args.case_file);
  apply_overrides(args, config);
  // 2. Mesh every part and build the model.
  return sf::build_model(config);
}

int run(const Arguments& args) {
  sf::Model model = load(args);
  print_model(model);
  // 3. Prepare the results folder and keep the resolved case beside the results.
  const fs::path out = output_directory(args, model.config);
  fs::create_directories(out);
  std::ofstream(out / "case.resolved.toml") << sf::format_resolved_case(model.config);
  sf::log_info("Results     {}\n\n", out.string());
  // 4. Run the explicit time loop (and springback when the case asks), or the static analysis.
  sf::RunOptions options;
  options.output_directory = out;
  const sf::RunSummary summary =
      model.config.analysis.type == sf::AnalysisConfig::Type::static_equilibrium
          ? sf::run_static(model, options)
          : sf::run_explicit(model, options);
  // 5. Report.
  sf::write_run_summary_json(summary, out / "summary.json");
  sf::log_info("\n{}", sf::format_run_summary(summary));
  sf::log_info("\nOpen in ParaView: {}  (one .xdmf per part: blank, {})\n",
               (out / "blank.xdmf").string(),
               model.tools.empty() ? std::string("no tools") : model.tools.front().name + ", ...");
  return sf::exit_ok;
}

int check(const Arguments& args) {
  const sf::Model model = load(args);
  print_model(model);
  sf::log_info("Case is valid.\n");
  return sf::exit_ok;
}

int mesh(const Arguments& args) {
  sf::Model model = load(args);
  print_model(model);
  const fs::path out = output_directory(args, model.config);
  fs::create_directories(out);
  sf::FrameOutput output(model, out);
  sf::SolutionState state = sf::make_initial_state(model);
  output.write_frame(model, state);
  output.flush();
  // Each part meshed from a .geo is also written as the .msh it made (gmsh ASCII 4.1), so a case
  // folder can keep its meshes beside their .geo files (scripts/update_case_meshes.sh).
  const sf::CaseConfig& c = model.config;
  auto write_msh_of = [&out](const std::string& part, const sf::MeshSourceConfig& mesh,
                             bool recombine) {
    if (mesh.file.extension() == ".geo") {
      sf::write_msh(mesh.file, mesh.element_size, recombine, out / (part + ".msh"));
    }
  };
  write_msh_of("blank", c.blank.mesh, c.blank.element == "quad");
  for (const sf::ToolConfig& t : c.tools) {
    write_msh_of(t.name, t.mesh, false);
  }
  sf::log_info(
      "Meshes written to {} (open blank.xdmf and the tools' .xdmf in ParaView; <part>.msh for "
      "each part meshed from a .geo)\n",
      out.string());
  return sf::exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sheetform: explicit finite-element simulation of sheet metal forming"};
  app.set_version_flag(
      "--version", std::string(sf::build_info::version) + " (" + sf::build_info::git_hash + ")");
  app.require_subcommand(1);
  Arguments args;
  auto add_common = [&args](CLI::App* sub) {
    sub->add_option("case", args.case_file, "the case file (case.toml)")
        ->required()
        ->check(CLI::ExistingFile);
    sub->add_flag("-q,--quiet", args.quiet, "print errors only");
    sub->add_flag("-v,--verbose", args.verbose,
                  "print more: gmsh's messages, every Newton iteration of a static step");
  };
  CLI::App* run_cmd = app.add_subcommand("run", "run a case and write results for ParaView");
  add_common(run_cmd);
  run_cmd->add_option("-o,--output", args.output_directory,
                      "results folder (default: the case's output.directory)");
  run_cmd->add_option("--stroke", args.stroke, "override the end condition: stroke in mm");
  run_cmd->add_option("--end-time", args.end_time, "override the end condition: end time in s");
  run_cmd
      ->add_option("--search", args.search,
                   "override the search of every [[contact]]: standard, modified or cached")
      ->check(CLI::IsMember(
          {"standard", "modified", "cached", "standard_brute_force", "modified_brute_force"}));
  CLI::App* check_cmd = app.add_subcommand("check", "validate a case and print its model");
  add_common(check_cmd);
  CLI::App* mesh_cmd = app.add_subcommand("mesh", "write only the meshes (HDF5 + XDMF)");
  add_common(mesh_cmd);
  mesh_cmd->add_option("-o,--output", args.output_directory, "results folder");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? sf::exit_ok : sf::exit_input_error;
  }
  if (args.quiet) {
    sf::verbosity() = sf::Verbosity::quiet;
  } else if (args.verbose) {
    sf::verbosity() = sf::Verbosity::verbose;
  }
  try {
    if (*run_cmd) {
      return run(args);
    }
    if (*check_cmd) {
      return check(args);
    }
    return mesh(args);
  } catch (const sf::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return sf::exit_input_error;
  } catch (const sf::InstabilityError& e) {
    std::cerr << "error: the run went unstable: " << e.what()
              << "\nThe frames written so far are readable in the results folder.\n";
    return sf::exit_unstable;
  } catch (const sf::ConvergenceError& e) {
    std::cerr << "error: the static step did not converge: " << e.what()
              << "\nThe frames written so far are readable in the results folder.\n";
    return sf::exit_not_converged;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return sf::exit_internal_error;
  }
}
