#pragma once
// One gmsh session, and gmsh's failures as InputError: used only inside the sandboxed child
// (meshing/gmsh_job.hpp), where gmsh reads and meshes a user's file.
#include <filesystem>
#include <functional>
#include <string>

namespace sf {

/// initialize on construction (no user configuration files, serial, errors thrown), finalize on
/// destruction; gmsh's terminal output only at Verbosity::verbose. gmsh::initialize sets the
/// OpenMP thread count to its own value: harmless in the child, whose threads are its own. (No
/// OpenMP call here: clang's OpenMP runtime, in the sanitizer builds, registers itself in
/// /dev/shm on its first call in a process, which the sandbox refuses.)
class GmshSession {
 public:
  GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
  ~GmshSession();

  /// gmsh's error messages logged so far (lines starting with "Error", and a repeated node tag of
  /// a .msh, which gmsh only notes), joined by newlines.
  static std::string logged_errors();
};

/// Runs one gmsh step; whatever gmsh throws or logs as an error becomes an InputError naming
/// `file` and the step ("reading the file"), with gmsh's messages.
void run_gmsh_step(const std::filesystem::path& file, const std::string& step,
                   const std::function<void()>& body);

}  // namespace sf
