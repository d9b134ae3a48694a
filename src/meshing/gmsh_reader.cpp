// The mesh reader's parent side: checks what can be checked before gmsh starts, runs gmsh in the
// sandbox, turns how the child ended into an InputError naming the file, reads the mesh it wrote.
#include "meshing/gmsh_reader.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "core/quoted.hpp"
#include "meshing/geo_safety.hpp"
#include "meshing/gmsh_job.hpp"
#include "meshing/msh_file.hpp"
#include "meshing/sandbox.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

/// Checks what can be checked before gmsh starts: the file exists, its extension, the sizes, and
/// (a .geo) the statements that run commands, for a friendly first message.
void check_mesh_source(const fs::path& file, double element_size, const MeshImportOptions& import,
                       std::span<const GeoParameter> parameters) {
  if (!fs::is_regular_file(file)) {
    throw InputError(quoted(file) + ": mesh file not found");
  }
  const MeshFormat format = mesh_format(file);
  if (!(element_size >= 0.0) || !std::isfinite(element_size)) {
    throw InputError(quoted(file) + ": element size must be >= 0 mm (0 = the file's own sizes)");
  }
  if (is_cad(format) && !(element_size > 0.0)) {
    throw InputError(quoted(file) +
                     ": a CAD file has no mesh sizes of its own: give the part an element_size "
                     "> 0 (mm)");
  }
  if (!(import.scale > 0.0) || !std::isfinite(import.scale)) {
    throw InputError(quoted(file) + ": scale must be > 0");
  }
  if (format == MeshFormat::geo && import.scale != 1.0) {
    throw InputError(quoted(file) +
                     ": a .geo script sets its own lengths: scale is for the other "
                     "formats");
  }
  if (format != MeshFormat::geo && !parameters.empty()) {
    throw InputError(quoted(file) +
                     ": parameters are set in a .geo file before gmsh parses it; a .msh file is "
                     "read as it is, and so are the other formats");
  }
  if (format == MeshFormat::geo) {
    check_geo_runs_no_commands(file);
  }
}

/// A fresh folder (mode 0700) under the system's temporary directory, removed with its content on
/// destruction: the only place the sandboxed child may write.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "sheetform-mesh-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw InputError(fmt::format("cannot make a scratch folder for gmsh in {}: {}",
                                   fs::temp_directory_path().string(), std::strerror(errno)));
    }
    path_ = pattern;
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

double machine_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

/// This process's address space (bytes): the forked child starts with all of it (its libraries,
/// the parent's heap), so its limit is this plus what gmsh may allocate.
double own_address_space_bytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0;
  statm >> pages;
  return pages * static_cast<double>(::sysconf(_SC_PAGESIZE));
}

/// The largest file the child may write: 1 kB per element allowed, and 1 GB (a binary MSH takes
/// about 60 bytes per triangle, an ASCII one about 120).
double max_output_bytes(const MeshLimits& limits) {
  return 1e9 + 1e3 * limits.max_elements;
}

SandboxPolicy policy_for(const fs::path& file, const fs::path& scratch, const MeshLimits& limits,
                         const MeshTimeLimit& time) {
  SandboxPolicy policy;
  const fs::path absolute = fs::absolute(file);
  policy.readable = {absolute.parent_path(), fs::weakly_canonical(absolute).parent_path()};
  policy.writable = scratch;
  policy.memory_bytes = own_address_space_bytes() +
                        (limits.memory_gb > 0.0 ? 1e9 * limits.memory_gb : machine_memory_bytes());
  policy.cpu_seconds = time.cpu_seconds();
  policy.max_file_bytes = max_output_bytes(limits);
  policy.keep_output = verbosity() >= Verbosity::verbose;
  // A user who trusts the case's .geo files lets them run commands: no confinement, limits kept.
  policy.confine = !geo_system_calls_allowed();
  return policy;
}

/// A small text file the child wrote (not a link: the child could point one anywhere).
std::string read_child_text(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) {
    return {};
  }
  std::string text(1 << 16, '\0');
  std::size_t done = 0;
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_nlink == 1) {
    for (ssize_t n;
         done < text.size() && (n = ::read(fd, text.data() + done, text.size() - done)) > 0;) {
      done += static_cast<std::size_t>(n);
    }
  }
  ::close(fd);
  text.resize(done);
  return text;
}

/// The error the child wrote: "input" or "parameter N" or "memory", then the message.
[[noreturn]] void throw_job_error(const fs::path& file, const fs::path& scratch,
                                  const MeshLimits& limits, const SandboxPolicy& policy) {
  const std::string text = read_child_text(scratch / GmshJobFiles::error);
  const std::size_t end = text.find('\n');
  const std::string kind = text.substr(0, end);
  const std::string message = end == std::string::npos ? std::string() : text.substr(end + 1);
  if (kind == "input" && !message.empty()) {
    // gmsh cannot open a file the sandbox keeps it from: say why.
    const bool confined = policy.confine && sandbox_support().landlock_abi > 0;
    throw InputError(message.find("Unable to open file") != std::string::npos && confined
                         ? message +
                               "\n(a case's mesh file may read only in its own folder and "
                               "write nothing there: docs/security.md)"
                         : message);
  }
  if (kind.rfind("parameter ", 0) == 0 && !message.empty()) {
    throw GeoParameterError(std::strtoul(kind.c_str() + 10, nullptr, 10), message);
  }
  if (kind == "memory") {
    const bool meshed = is_meshed(mesh_format(file));
    throw InputError(
        fmt::format("{}: gmsh ran out of memory {} it ({:.3g} GB allowed{}); {}", quoted(file),
                    meshed ? "reading and meshing" : "reading",
                    limits.memory_gb > 0.0 ? limits.memory_gb : machine_memory_bytes() / 1e9,
                    limits.memory_gb > 0.0 ? ": limits.mesh_memory_gb" : ", this machine's memory",
                    meshed ? "far too fine a mesh, or a damaged file?"
                           : "the file claims far more than it holds (damaged?)"));
  }
  throw InputError(quoted(file) + ": gmsh stopped without saying why (no mesh written)");
}

std::string signal_name(int signal) {
  const char* name = ::strsignal(signal);
  return name != nullptr ? std::string(name) : fmt::format("signal {}", signal);
}

/// Runs gmsh on `job` in the sandbox; returns normally when the mesh is in the scratch folder.
void run_job(const GmshJob& job, const fs::path& scratch, const MeshLimits& limits) {
  MeshTimeLimit time(limits, static_cast<double>(fs::file_size(job.file)));
  const SandboxPolicy policy = policy_for(job.file, scratch, limits, time);
  const SandboxOutcome outcome = run_sandboxed(
      policy, [&](const SandboxReporter& reporter) { return run_gmsh_job(job, scratch, reporter); },
      [&time](const std::string& report) { return time.seconds_for(report); });
  const std::string file = quoted(job.file);
  switch (outcome.end) {
    case SandboxOutcome::End::exited:
      if (outcome.status == 0) {
        if (!fs::is_regular_file(fs::symlink_status(scratch / GmshJobFiles::mesh))) {
          throw InputError(file +
                           ": gmsh ended before writing the mesh (an Exit statement in "
                           "the file?)");
        }
        return;
      }
      if (outcome.status == 1) {
        throw_job_error(job.file, scratch, limits, policy);
      }
      if (outcome.last_report == "!unconfined") {
        throw std::runtime_error(file + ": the sandbox for gmsh could not be set up");
      }
      throw InputError(
          fmt::format("{}: gmsh ended with status {} while reading it", file, outcome.status));
    case SandboxOutcome::End::crashed:
      throw InputError(fmt::format(
          "{}: gmsh crashed reading it ({}): the file is damaged, or not a file gmsh 4.8 and "
          "OpenCASCADE read; write it again from its program",
          file, signal_name(outcome.signal)));
    case SandboxOutcome::End::refused_call:
      throw InputError(fmt::format(
          "{}: reading it tried to start a program or a process (system call {}), which a case "
          "file may not: gmsh was stopped (docs/security.md). A .geo runs commands with "
          "SystemCall, "
          "NonBlockingSystemCall or OnelabRun; if the file is your own and you trust it, give "
          "--allow-geo-system-calls",
          file, outcome.refused_call));
    case SandboxOutcome::End::cpu_limit:
      throw InputError(
          fmt::format("{}: gmsh used its CPU-time limit of {:.0f} s reading and meshing it; set "
                      "limits.mesh_seconds to give it longer",
                      file, policy.cpu_seconds));
    case SandboxOutcome::End::file_limit:
      throw InputError(fmt::format(
          "{}: gmsh tried to write a file larger than {:.3g} GB (limits.max_elements sets it)",
          file, policy.max_file_bytes / 1e9));
    case SandboxOutcome::End::deadline:
      throw InputError(file + ": " + time.explain(outcome.last_report, outcome.deadline_s));
  }
  throw std::logic_error("unknown sandbox outcome");
}

GmshJob make_job(const fs::path& file, double element_size, bool recombine,
                 std::span<const GeoParameter> parameters, const MeshImportOptions& import,
                 const MeshLimits& limits) {
  GmshJob job;
  job.file = file;
  job.element_size = element_size;
  job.recombine = recombine;
  job.parameters.assign(parameters.begin(), parameters.end());
  job.import = import;
  job.max_elements = limits.max_elements;
  return job;
}

/// Copies the child's ASCII mesh to `out` (written by this process, not by the child).
void copy_child_file(const fs::path& from, const fs::path& out) {
  const std::string failed = quoted(out) + ": cannot write the mesh file";
  const int in = ::open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (in < 0) {
    throw InputError(failed + ": gmsh did not write it");
  }
  std::ofstream target(out, std::ios::binary | std::ios::trunc);
  char buffer[1 << 16];
  for (ssize_t n; target && (n = ::read(in, buffer, sizeof(buffer))) > 0;) {
    target.write(buffer, n);
  }
  ::close(in);
  target.close();
  if (!target) {
    throw InputError(failed + ": " + std::strerror(errno));
  }
}

}  // namespace

GmshModel load_gmsh_model(const fs::path& file, double element_size, bool recombine,
                          std::span<const GeoParameter> parameters, const MeshImportOptions& import,
                          const MeshLimits& limits) {
  check_mesh_source(file, element_size, import, parameters);
  const ScratchFolder scratch;
  run_job(make_job(file, element_size, recombine, parameters, import, limits), scratch.path(),
          limits);
  GmshModel model =
      read_msh41_binary(scratch.path() / GmshJobFiles::mesh, file, max_output_bytes(limits));
  check_model_has_groups(model);
  if (!is_cad(mesh_format(file))) {
    model.node_coords *= import.scale;  // CAD files are scaled by OpenCASCADE as they are read
  }
  return model;
}

void write_msh(const fs::path& geo_file, double element_size, bool recombine,
               const fs::path& msh_out, std::span<const GeoParameter> parameters,
               const MeshLimits& limits) {
  check_mesh_source(geo_file, element_size, MeshImportOptions{}, parameters);
  const ScratchFolder scratch;
  GmshJob job = make_job(geo_file, element_size, recombine, parameters, {}, limits);
  job.ascii_copy = true;
  run_job(job, scratch.path(), limits);
  // The same checks as load_gmsh_model (empty mesh, no groups) before the file is kept.
  check_model_has_groups(
      read_msh41_binary(scratch.path() / GmshJobFiles::mesh, geo_file, max_output_bytes(limits)));
  copy_child_file(scratch.path() / GmshJobFiles::ascii_mesh, msh_out);
}

}  // namespace sf
