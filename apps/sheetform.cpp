// sheetform: explicit finite-element simulation of sheet metal forming, with springback and
// static analyses by an implicit static step.
//
//   sheetform run   CASE [-o DIR]   run a case, write results (HDF5 + XDMF for ParaView)
//   sheetform check CASE            validate a case and print the model it builds
//   sheetform mesh  CASE [-o DIR]   write only the meshes (HDF5 + XDMF, and .msh of each .geo)
//   sheetform schema [--markdown]   print the case file's keys (the tables of docs/case-file.md)
//
// run takes --threads N (OpenMP; default OMP_NUM_THREADS, else every core): the results are the
// same bits for any thread count (docs/parallel.md). Started by mpirun (mpirun -np N sheetform
// run CASE), the ranks share the blank (METIS parts) and give the same bits again; rank 0 prints
// and writes the results.
//
// Each takes --set KEY=VALUE (repeatable): a case-file key overridden before the case is read,
// e.g. --set blank.parameters.n=32 for a .geo parameter (docs/case-file.md).
//
// run --restart CHECKPOINT continues a run from its checkpoint (written every
// control.checkpoint_minutes, on SIGUSR1, on Ctrl-C or SIGTERM, and at the end of the forming),
// bit for bit as if it had not stopped (docs/restart.md).
//
// Exit codes: 0 success, 2 bad input, 3 the run went unstable, 4 a static step did not converge
// (or its stiffness is singular), 5 stopped by Ctrl-C or SIGTERM (a checkpoint written; continue
// with --restart), 6 the results could not be written (a full disk), 1 an internal error.
#include <fmt/core.h>
#include <omp.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>

#include "casefile/case_config.hpp"
#include "casefile/case_fields.hpp"
#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "core/log.hpp"
#include "meshing/geo_safety.hpp"
#include "meshing/gmsh_reader.hpp"
#include "meshing/sandbox.hpp"
#include "model/build_model.hpp"
#include "model/constraint_assembly.hpp"
#include "parallel/mpi_domain.hpp"
#include "parallel/mpi_session.hpp"
#include "solver/case_digest.hpp"
#include "solver/case_model.hpp"
#include "solver/checkpoint.hpp"
#include "solver/dynain_writer.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/formed_part.hpp"
#include "solver/frame_output.hpp"
#include "solver/model_report.hpp"
#include "solver/run_estimate.hpp"
#include "solver/static_driver.hpp"
#include "solver/stop_request.hpp"
#include "solver/tool_mesh_report.hpp"

namespace fs = std::filesystem;

namespace {

struct Arguments {
  std::string case_file;
  std::string output_directory;
  std::optional<double> stroke;         // mm; none = as in the case
  std::optional<double> end_time;       // s; none = as in the case
  std::string search;                   // "" = as in the case; else the search of every [[contact]]
  std::vector<std::string> set;         // --set KEY=VALUE: case-file keys overridden before reading
  int threads = 0;                      // 0 = OMP_NUM_THREADS, else every core
  bool allow_geo_system_calls = false;  // --allow-geo-system-calls
  std::string restart;                  // --restart CHECKPOINT; "" = from time 0
  bool overwrite = false;               // --overwrite: replace an earlier run's results
  long stop_at_cycle = -1;              // --stop-at-cycle N: a clean stop as on SIGTERM
  bool quiet = false;
  bool verbose = false;
};

// A whole-number option's check, saying what is expected (CLI11's own says "Value two not in
// range 1 to 4096"): "expected a whole number of threads >= 1, got 'two'".
CLI::Validator whole_number(const std::string& what, long lo, long hi) {
  auto check = [what, lo, hi](std::string& text) -> std::string {
    long value = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    const bool whole = error == std::errc() && stop == end;
    if (whole && value >= lo && value <= hi) {
      return {};
    }
    return fmt::format("expected a whole number of {} >= {}{}, got '{}'", what, lo,
                       whole && value > hi ? fmt::format(" and at most {}", hi) : std::string(),
                       text);
  };
  return CLI::Validator(check, fmt::format("{} >= {}", what, lo));
}

// The command-line options that change the case, applied before it is read (read_case).
sf::CaseOptions case_options(const Arguments& args) {
  sf::CaseOptions options{.set = args.set, .stroke = args.stroke, .end_time = args.end_time};
  if (!args.search.empty()) {
    options.search = sf::find_choice<sf::ContactSearchKind>(sf::kContactSearchNames, args.search);
  }
  return options;
}

fs::path output_directory(const Arguments& args, const sf::CaseConfig& config) {
  if (!args.output_directory.empty()) {
    return fs::absolute(args.output_directory);
  }
  return config.file.parent_path() / config.output.directory;
}

// A case read and the model built from it.
struct LoadedCase {
  sf::CaseConfig config;
  sf::Model model;
  sf::RunEstimate estimate;
};

LoadedCase load(const Arguments& args) {
  // 1. Read and validate the case file.
  sf::CaseConfig config = sf::read_case(args.case_file, case_options(args));
  // 2. Mesh every part and build the model.
  sf::Model model = sf::build_case_model(config);
  // 3. What it will cost, and what it asks for beyond the case's limits (refused here).
  sf::RunEstimate estimate = sf::estimate_run(config, model);
  sf::enforce_run_limits(config, estimate);
  return {std::move(config), std::move(model), std::move(estimate)};
}

// The results folder, made if missing; a path that cannot be a folder is bad input.
void create_results_folder(const fs::path& out) {
  std::error_code error;
  fs::create_directories(out, error);
  if (error || !fs::is_directory(out)) {
    throw sf::InputError(fmt::format(
        "results folder {}: cannot create it ({}); give -o a folder path whose parents are "
        "folders you can write to",
        out.string(), error ? error.message() : "a file has that name"));
  }
}

// The files a run writes in its results folder (besides one .xdmf per part).
constexpr const char* kRunFiles[] = {"results.h5",        "summary.json",       "checkpoint.h5",
                                     "checkpoint.h5.tmp", "case.resolved.toml", "formed_part.h5",
                                     "formed_part.h5.tmp"};

// A write's temporary files (<part>.xdmf.tmp, checkpoint.h5.tmp) are left only when every process
// of a run was killed at once inside a write (docs/results-format.md): the next run in the folder
// removes them.
bool is_leftover_temporary(const fs::path& file) {
  return file.filename() == "checkpoint.h5.tmp" ||
         (sf::is_formed_part_file(file) && file.extension() == ".tmp") ||
         (file.extension() == ".tmp" && file.stem().extension() == ".xdmf");
}

void remove_leftover_temporaries(const fs::path& out) {
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(out, error)) {
    if (is_leftover_temporary(entry.path())) {
      fs::remove(entry.path(), error);
    }
  }
}

// A folder holding an earlier run's results is not mixed with a new run: refused, unless
// --overwrite, which removes that run's files (and only those) first. A restart goes on in it.
void clear_earlier_run(const Arguments& args, const fs::path& out) {
  if (!args.restart.empty()) {
    remove_leftover_temporaries(out);
    return;
  }
  std::vector<fs::path> earlier;
  for (const char* name : kRunFiles) {
    if (fs::exists(out / name)) {
      earlier.push_back(out / name);
    }
  }
  if (earlier.empty()) {
    return;
  }
  if (!args.overwrite) {
    throw sf::InputError(fmt::format(
        "results folder {} holds the results of an earlier run ({}); give --overwrite to replace "
        "them, -o another folder, or --restart {} to continue that run",
        out.string(), earlier.front().filename().string(), sf::checkpoint_path(out).string()));
  }
  for (const fs::directory_entry& entry : fs::directory_iterator(out)) {
    if (entry.path().extension() == ".xdmf" || is_leftover_temporary(entry.path()) ||
        (sf::is_formed_part_file(entry.path()) && entry.path() != out / "formed_part.h5")) {
      earlier.push_back(entry.path());
    }
  }
  for (const fs::path& file : earlier) {
    std::error_code error;
    fs::remove(file, error);
    if (error) {
      throw sf::InputError(
          fmt::format("--overwrite: cannot remove {} ({})", file.string(), error.message()));
    }
  }
}

// A folder (or anything but a file) where a command writes a file in the results folder is bad
// input, said before any work: the first frame's rename onto it would fail (an internal error).
// `extensions`: the files written per part ("blank.xdmf", ...).
void check_result_paths(const fs::path& out, const sf::Model& model,
                        std::initializer_list<const char*> extensions) {
  std::vector<fs::path> paths(std::begin(kRunFiles), std::end(kRunFiles));
  for (fs::path& p : paths) {
    p = out / p;
  }
  std::vector<std::string> parts{"blank"};
  for (const sf::Tool& tool : model.tools) {
    parts.push_back(tool.name);
  }
  for (const std::string& part : parts) {
    for (const char* extension : extensions) {
      paths.push_back(out / (part + extension));
    }
  }
  for (const fs::path& path : paths) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (fs::exists(status) && !fs::is_regular_file(status)) {
      throw sf::InputError(fmt::format(
          "results folder {}: {} is {}, where the run writes a file; remove or rename it, or give "
          "-o another folder",
          out.string(), path.string(),
          fs::is_directory(status) ? "a folder" : "not a regular file"));
    }
  }
}

// Rank 0 prepares the results folder and keeps the resolved case beside the results; every rank
// learns whether that worked (a failure met by rank 0 alone must not leave the others waiting).
void prepare_results_folder(const sf::MpiSession& mpi, const Arguments& args, const fs::path& out,
                            const sf::Model& model) {
  const std::string& resolved_case = model.output.resolved_case;
  std::string problem;
  if (mpi.rank() == 0) {
    try {
      create_results_folder(out);
      check_result_paths(out, model, {".xdmf", ".xdmf.tmp"});
      clear_earlier_run(args, out);
      std::ofstream file(out / "case.resolved.toml");
      file << resolved_case;
      if (!file) {
        problem = "cannot write " + (out / "case.resolved.toml").string();
      }
    } catch (const std::exception& e) {
      problem = e.what();
    }
  }
  problem = mpi.broadcast_from_root(problem);
  if (!problem.empty()) {
    throw sf::InputError(problem);
  }
}

// The share of the blank this rank computes (nullptr: all of it, a serial run). A static
// analysis is computed whole on rank 0 (its solver, CHOLMOD's, is a serial direct solver).
std::shared_ptr<sf::Domain> make_domain(const sf::MpiSession& mpi, const sf::Model& model,
                                        const std::string& case_file) {
  if (mpi.size() <= 1 || model.analysis.is_static()) {
    return nullptr;
  }
  if (!mpi.same_on_all_ranks(sf::mesh_digest(model))) {
    throw sf::InputError(case_file +
                         ": the MPI ranks built different meshes from the case (gmsh gave a "
                         "different mesh on some rank); write the meshes once with `sheetform "
                         "mesh` and give the .msh files in the case");
  }
  const sf::ShellPart& part = model.blank.part;
  try {
    return std::make_shared<sf::MpiDomain>(part.quads, part.triangles,
                                           static_cast<int>(model.blank.mesh.nodes.cols()),
                                           MPI_COMM_WORLD);
  } catch (const std::invalid_argument& e) {
    throw sf::InputError(case_file + ": " + e.what());
  }
}

void print_parallel_banner(const sf::MpiSession& mpi, const sf::Model& model) {
  const int threads = omp_get_max_threads();
  const bool crowded = threads > 1 && threads * mpi.local_size() > omp_get_num_procs() &&
                       std::getenv("OMP_WAIT_POLICY") == nullptr;
  const char* advice = crowded ? "; more threads than cores: set OMP_WAIT_POLICY=passive, or "
                                 "waiting threads spin and slow the run"
                               : "";
  const int cores = omp_get_num_procs();
  if (mpi.size() > 1 && model.analysis.is_static()) {
    sf::log_info(
        "Ranks       {} (MPI): the static analysis runs on rank 0 alone, {} thread{} (its solver, "
        "CHOLMOD's, is a serial direct solver); the other ranks wait{}\n\n",
        mpi.size(), threads, threads == 1 ? "" : "s", advice);
    return;
  }
  if (mpi.size() > 1) {
    sf::log_info("Ranks       {} (MPI), {} thread{} each (OpenMP; {} core{} for rank 0){}\n\n",
                 mpi.size(), threads, threads == 1 ? "" : "s", cores, cores == 1 ? "" : "s",
                 advice);
    return;
  }
  sf::log_info("Threads     {} (OpenMP, {} core{} here){}\n\n", threads, cores,
               cores == 1 ? "" : "s", advice);
}

// What to do once the results folder can be written again: go on from this run's last
// checkpoint when there is one (or from the one it restarted from), else run the case again.
std::string how_to_go_on(const Arguments& args, const sf::CaseConfig& config, const fs::path& out) {
  std::error_code error;
  fs::path checkpoint = sf::checkpoint_path(out);
  if (!fs::is_regular_file(checkpoint, error)) {
    checkpoint = args.restart.empty() ? fs::path() : fs::absolute(args.restart);
  }
  if (!checkpoint.empty()) {
    return fmt::format(
        "\nOnce the results folder can be written again (free some space), continue from the last "
        "checkpoint: "
        "sheetform run {} --restart {} -o {} (with this run's --set, --search, --stroke or "
        "--end-time options)",
        config.file.string(), checkpoint.string(), out.string());
  }
  const sf::ControlConfig& control = config.control;
  return fmt::format(
      "\nNo checkpoint of this run was written before it stopped (one is written every "
      "control.checkpoint_minutes = {:g} min of wall time{}), so there is none to continue from: "
      "once the folder can be written again (free some space), run the case again with "
      "--overwrite (or -o another folder)",
      control.checkpoint_minutes,
      control.checkpoint_cycles > 0
          ? fmt::format(" and every control.checkpoint_cycles = {} cycles",
                        control.checkpoint_cycles)
          : std::string());
}

int run(const Arguments& args, const sf::MpiSession& mpi) {
  sf::install_run_request_handlers();  // a Ctrl-C while meshing stops at the first cycle
  const LoadedCase loaded = load(args);
  const sf::Model& model = loaded.model;
  if (model.analysis.is_static()) {
    sf::restore_default_signal_actions();  // a static analysis has no cycles to stop at
  }
  sf::RunOptions options;
  options.domain = make_domain(mpi, model, loaded.config.file.string());
  // After a trim: the model built on the trimmed part, split over the ranks afresh.
  options.rebuild.model = [&loaded](const sf::BlankMesh& blank) {
    return sf::build_model(loaded.config, &blank);
  };
  options.rebuild.domain = [&mpi, &loaded](const sf::Model& trimmed) {
    return make_domain(mpi, trimmed, loaded.config.file.string());
  };
  sf::print_model(loaded.config, model);
  sf::print_run_estimate(loaded.estimate, model);
  sf::report_tool_meshes(loaded.config, model);
  // 3. Prepare the results folder and keep the resolved case beside the results.
  const fs::path out = output_directory(args, loaded.config);
  if (!args.restart.empty() && model.analysis.is_static()) {
    throw sf::InputError("--restart continues an explicit run; " + loaded.config.file.string() +
                         " is a static analysis ([analysis] type = \"static\")");
  }
  prepare_results_folder(mpi, args, out, model);
  sf::log_info("Results     {}\n", out.string());
  print_parallel_banner(mpi, model);
  if (model.analysis.is_static() && mpi.rank() != 0) {
    return sf::exit_ok;  // rank 0 computes and reports the static analysis
  }
  // 4. Run the explicit time loop (and springback when the case asks), or the static analysis.
  options.output_directory = out;
  options.restart_file = args.restart.empty() ? fs::path() : fs::absolute(args.restart);
  options.stop_at_cycle = args.stop_at_cycle;
  const sf::RunSummary summary = [&] {
    try {
      return model.analysis.is_static() ? sf::run_static(model, options)
                                        : sf::run_explicit(model, options);
    } catch (const sf::OutputError& e) {
      throw sf::OutputError(e.what() + how_to_go_on(args, loaded.config, out));
    }
  }();
  if (mpi.rank() != 0) {
    return sf::exit_ok;  // rank 0 reports
  }
  // 5. Report.
  sf::write_run_summary_json(summary, out / "summary.json");
  sf::log_info("\n{}", sf::format_run_summary(summary));
  sf::log_info("\nOpen in ParaView: {}  (one .xdmf per part: blank, {})\n",
               (out / "blank.xdmf").string(),
               model.tools.empty() ? std::string("no tools") : model.tools.front().name + ", ...");
  return sf::exit_ok;
}

int check(const Arguments& args) {
  const LoadedCase loaded = load(args);
  sf::print_model(loaded.config, loaded.model);
  sf::print_run_estimate(loaded.estimate, loaded.model);
  sf::report_tool_meshes(loaded.config, loaded.model);
  if (sf::geo_system_calls_allowed()) {
    sf::log_info(
        "Sandbox     off (--allow-geo-system-calls): gmsh read the mesh files "
        "unconfined, under its limits only\n");
  } else {
    sf::log_info("Sandbox     gmsh reads the mesh files in a sandbox: {}\n",
                 sf::sandbox_support().describe());
  }
  sf::log_info("Case is valid.\n");
  return sf::exit_ok;
}

int mesh(const Arguments& args, const sf::MpiSession& mpi) {
  const LoadedCase loaded = load(args);
  if (mpi.rank() != 0) {
    return sf::exit_ok;  // rank 0 writes
  }
  const sf::Model& model = loaded.model;
  sf::print_model(loaded.config, model);
  sf::print_run_estimate(loaded.estimate, model);
  const fs::path out = output_directory(args, loaded.config);
  create_results_folder(out);
  check_result_paths(out, model, {".xdmf", ".xdmf.tmp", ".msh"});
  sf::FrameOutput output(model, out);
  sf::SolutionState state = sf::make_initial_state(model);
  output.write_frame(model, state);
  output.flush();
  // Each part meshed from a .geo is also written as the .msh it made (gmsh ASCII 4.1), so a case
  // folder can keep its meshes beside their .geo files (scripts/update_case_meshes.sh).
  const sf::CaseConfig& c = loaded.config;
  auto write_msh_of = [&out, &c](const std::string& part, const sf::MeshSourceConfig& mesh,
                                 bool recombine) {
    if (mesh.file.extension() == ".geo") {
      sf::write_msh(mesh.file, mesh.element_size, recombine, out / (part + ".msh"), mesh.parameters,
                    sf::mesh_limits(c.limits));
    }
  };
  write_msh_of("blank", c.blank.mesh, c.blank.element == sf::BlankMeshing::quad);
  for (const sf::ToolConfig& t : c.tools) {
    write_msh_of(t.name, t.mesh, false);
  }
  sf::log_info(
      "Meshes written to {} (open blank.xdmf and the tools' .xdmf in ParaView; <part>.msh for "
      "each part meshed from a .geo)\n",
      out.string());
  return sf::exit_ok;
}

// Writes a formed part as a dynain file beside it (or at `output`).
int dynain(const std::string& part_file, const std::string& output) {
  const sf::FormedPart part = sf::read_formed_part(part_file);
  fs::path file = output;
  if (file.empty()) {
    file = fs::path(part_file).replace_extension(".dynain");
  }
  sf::write_dynain(part, file);
  sf::log_info("Wrote {} ({} nodes, {} shells, {} points through the thickness)\n", file.string(),
               part.reference_nodes.cols(), part.quads.cols() + part.triangles.cols(),
               part.n_points);
  return sf::exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
  std::optional<sf::MpiSession> mpi;
  try {
    mpi.emplace(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "internal error: MPI: " << e.what() << "\n";
    return sf::exit_internal_error;
  }
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
    sub->add_flag("--allow-geo-system-calls", args.allow_geo_system_calls,
                  "let the case's .geo files run commands (SystemCall, OnelabRun) and Exit: only "
                  "for files you trust");
    sub->add_flag("-v,--verbose", args.verbose,
                  "print more: gmsh's messages, every Newton iteration of a static step");
    sub->add_option("--set", args.set,
                    "override a case-file key before the case is read, KEY=VALUE with KEY a "
                    "dotted path (blank.parameters.n=32, tools[1].element_size=1.5, "
                    "control.output_frames=10) and VALUE a TOML value; repeatable")
        ->allow_extra_args(false);
  };
  CLI::App* run_cmd = app.add_subcommand("run", "run a case and write results for ParaView");
  add_common(run_cmd);
  run_cmd->add_option("-o,--output", args.output_directory,
                      "results folder (default: the case's output.directory)");
  run_cmd->add_option("--restart", args.restart,
                      "continue the run from this checkpoint (<results>/checkpoint.h5); the "
                      "results go on in the same folder; --stroke or --end-time may extend it");
  run_cmd->add_flag("--overwrite", args.overwrite,
                    "replace the results of an earlier run in the results folder (refused "
                    "without it)");
  run_cmd
      ->add_option("--stop-at-cycle", args.stop_at_cycle,
                   "stop cleanly at the end of cycle N as on SIGTERM (last frame, checkpoint, "
                   "exit 5), to look at an early state or to test a restart")
      ->check(whole_number("cycles", 1, std::numeric_limits<long>::max()));
  run_cmd->add_option("--stroke", args.stroke, "override the end condition: stroke in mm");
  run_cmd->add_option("--end-time", args.end_time, "override the end condition: end time in s");
  run_cmd
      ->add_option("--threads", args.threads,
                   "OpenMP threads (default: OMP_NUM_THREADS, else every core); results are the "
                   "same bits for any count")
      ->check(whole_number("threads", 1, 4096));
  run_cmd
      ->add_option("--search", args.search,
                   "override the search of every [[contact]]: standard, modified or cached")
      ->check(CLI::IsMember(sf::choice_names<sf::ContactSearchKind>(sf::kContactSearchNames)));
  CLI::App* check_cmd = app.add_subcommand("check", "validate a case and print its model");
  add_common(check_cmd);
  CLI::App* mesh_cmd = app.add_subcommand("mesh", "write only the meshes (HDF5 + XDMF)");
  add_common(mesh_cmd);
  mesh_cmd->add_option("-o,--output", args.output_directory, "results folder");
  CLI::App* dynain_cmd = app.add_subcommand(
      "dynain", "write a formed part as an LS-DYNA keyword file (docs/process-chain.md)");
  std::string dynain_part, dynain_output;
  dynain_cmd->add_option("part", dynain_part, "the formed part (<results>/formed_part.h5)")
      ->required()
      ->check(CLI::ExistingFile);
  dynain_cmd->add_option("-o,--output", dynain_output,
                         "the keyword file (default: the part's name with .dynain)");
  dynain_cmd->add_flag("-q,--quiet", args.quiet, "print errors only");
  CLI::App* schema_cmd =
      app.add_subcommand("schema", "print the case file's keys, section by section");
  bool markdown = false;
  schema_cmd->add_flag("--markdown", markdown,
                       "as the Markdown tables of docs/case-file.md, between their marker lines");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? sf::exit_ok : sf::exit_input_error;
  }
  if (*schema_cmd) {
    std::cout << (markdown ? sf::case_schema_markdown() : sf::case_schema_text());
    return sf::exit_ok;
  }
  sf::geo_system_calls_allowed() = args.allow_geo_system_calls;
  if (mpi->rank() != 0) {  // one rank speaks
    sf::verbosity() = sf::Verbosity::quiet;
    sf::warnings_enabled() = false;
  }
  if (args.threads > 0) {
    omp_set_num_threads(args.threads);  // before gmsh: its session restores this count
  } else if (mpi->size() > 1 && std::getenv("OMP_NUM_THREADS") == nullptr) {
    // The ranks on this machine share its cores.
    omp_set_num_threads(std::max(1, omp_get_num_procs() / std::max(1, mpi->local_size())));
  }
  if (args.quiet) {
    sf::verbosity() = sf::Verbosity::quiet;
  } else if (args.verbose && mpi->rank() == 0) {
    sf::verbosity() = sf::Verbosity::verbose;
  }
  // Input errors and instabilities are met by every rank together (the same input; the ranks
  // agree on every failure in the time loop), or by rank 0 alone after the others are done (its
  // springback, its report), so rank 0 alone reports them. Anything else may be one rank's alone
  // while the others wait for it: it ends the whole run.
  const bool speaks = mpi->rank() == 0;
  // Every rank ends with one barrier, on success and on error alike, so that none exits before
  // rank 0 has reported (the launcher kills the others when one exits with an error).
  try {
    const int code = *run_cmd      ? run(args, *mpi)
                     : *check_cmd  ? check(args)
                     : *dynain_cmd ? dynain(dynain_part, dynain_output)
                                   : mesh(args, *mpi);
    mpi->barrier();
    return code;
  } catch (const sf::InputError& e) {
    if (speaks) {
      std::cerr << "error: " << e.what() << "\n";
    }
    mpi->barrier();
    return sf::exit_input_error;
  } catch (const sf::InstabilityError& e) {
    if (speaks) {
      std::cerr << "error: the run went unstable: " << e.what()
                << "\nThe frames written so far are readable in the results folder.\n";
    }
    mpi->barrier();
    return sf::exit_unstable;
  } catch (const sf::RunStopped& e) {
    if (speaks) {
      std::cerr << e.what() << "\n";
    }
    mpi->barrier();
    return sf::exit_stopped;
  } catch (const sf::OutputError& e) {
    std::cerr << "error: " << e.what()
              << "\nWhat was written before is readable in the results folder.\n";
    if (mpi->size() > 1) {
      mpi->abort(sf::exit_output_error);  // rank 0's alone: the others may be waiting
    }
    return sf::exit_output_error;
  } catch (const sf::ConvergenceError& e) {
    if (speaks) {
      std::cerr << "error: the static step did not converge: " << e.what()
                << "\nThe frames written so far are readable in the results folder.\n";
    }
    mpi->barrier();
    return sf::exit_not_converged;
  } catch (const std::exception& e) {
    if (mpi->size() > 1) {
      std::cerr << "internal error (MPI rank " << mpi->rank() << "): " << e.what() << "\n";
      mpi->abort(sf::exit_internal_error);
    }
    std::cerr << "internal error: " << e.what() << "\n";
    return sf::exit_internal_error;
  }
}
