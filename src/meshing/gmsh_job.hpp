#pragma once
// What the sandboxed child does with a user's mesh source: gmsh reads it (and meshes a .geo or
// CAD file), and writes the result as MSH 4.1 into the scratch folder, or the error into a file
// there. Nothing else crosses back: the parent reads those files (meshing/msh_file.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include "meshing/geo_parameter.hpp"
#include "meshing/mesh_import.hpp"
#include "meshing/sandbox.hpp"

namespace sf {

struct GmshJob {
  std::filesystem::path file;  ///< the user's mesh source (absolute)
  double element_size = 0.0;   ///< mm; 0 = the file's own sizes (.geo), required > 0 for CAD
  bool recombine = false;      ///< quads (a blank)
  std::vector<GeoParameter> parameters;  ///< .geo only
  MeshImportOptions import;
  double max_elements = 5e6;  ///< refused above, before meshing
  bool ascii_copy = false;    ///< also write the mesh as ASCII MSH 4.1 (`sheetform mesh`)
};

/// The files the job leaves in the scratch folder.
struct GmshJobFiles {
  static constexpr const char* mesh = "mesh.msh";              ///< binary MSH 4.1
  static constexpr const char* ascii_mesh = "mesh_ascii.msh";  ///< ASCII MSH 4.1 (ascii_copy)
  static constexpr const char* error = "error.txt";  ///< "input" or "parameter N", then the text
};

/// The stages it reports, in order (the parent gives each its time: meshing/mesh_time_limit.hpp).
struct GmshJobStage {
  static constexpr const char* reading = "reading";    ///< the file is being read
  static constexpr const char* estimate = "estimate";  ///< "estimate N": N elements to mesh
  static constexpr const char* writing = "writing";    ///< writing the mesh
};

/// Runs in the sandboxed child: returns 0 with GmshJobFiles::mesh written, or 1 with
/// GmshJobFiles::error written (an InputError's or GeoParameterError's message, or running out
/// of memory).
int run_gmsh_job(const GmshJob& job, const std::filesystem::path& scratch,
                 const SandboxReporter& reporter);

}  // namespace sf
