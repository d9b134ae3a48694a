#include "meshing/gmsh_job.hpp"

#include <fmt/core.h>

#include <gmsh.h>
#include <fstream>
#include <new>

#include "core/errors.hpp"
#include "core/quoted.hpp"
#include "meshing/chord_error_size.hpp"
#include "meshing/file_completeness.hpp"
#include "meshing/geo_parameters.hpp"
#include "meshing/gmsh_session.hpp"
#include "meshing/mesh_size_estimate.hpp"

namespace sf {
namespace {

void set_sizes(const GmshJob& job, MeshFormat format) {
  if (is_meshed(format) && job.element_size > 0.0) {
    gmsh::option::setNumber("Mesh.MeshSizeMax", job.element_size);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  }
  if (is_cad(format) && job.import.curvature_elements > 0) {
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", job.import.curvature_elements);
  }
}

void open_file(const GmshJob& job, MeshFormat format, const std::filesystem::path& scratch) {
  run_gmsh_step(job.file, "setting options", [&] {
    set_sizes(job, format);
    if (is_cad(format)) {
      set_cad_read_options(format, job.import);
    }
  });
  if (job.parameters.empty()) {
    run_gmsh_step(job.file, "reading the file", [&] { gmsh::open(job.file.string()); });
  } else {
    open_with_parameters(job.file, job.parameters, scratch);
  }
}

// Refuses an element size that asks gmsh for more elements than the limit, before gmsh tries;
// tells the parent the count, which sets the meshing's time.
void check_element_count(const GmshJob& job, const SandboxReporter& reporter) {
  double area = 0.0, elements = 0.0;
  run_gmsh_step(job.file, "estimating the mesh size", [&] {
    area = estimated_surface_area();
    elements = estimate_element_count(job.element_size, job.recombine);
  });
  if (elements > job.max_elements) {
    throw InputError(fmt::format(
        "{}: element_size = {:g} mm asks gmsh for about {:.2g} elements (surfaces of about "
        "{:.4g} mm^2), more than limits.max_elements = {:.3g}; give a larger element_size, or "
        "raise limits.max_elements",
        quoted(job.file), job.element_size, elements, area, job.max_elements));
  }
  reporter.report(fmt::format("{} {:.0f}", GmshJobStage::estimate, elements));
}

void mesh_surfaces(const GmshJob& job, MeshFormat format) {
  run_gmsh_step(job.file, "meshing in 2-D", [&] {
    set_sizes(job, format);
    if (is_cad(format) && job.import.chord_error > 0.0) {
      set_chord_error_size(job.import.chord_error);
    }
    if (job.recombine) {
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
      // Frontal-Delaunay triangles, recombined (Blossom). Not Frontal-Delaunay for quads (8):
      // gmsh 4.8.4 (Debian 12) crashes with it on a face read from a CAD file
      // (backgroundMesh::getAngle, seen on a plane from STEP) and on every unstructured surface
      // of a .geo tried, down to a 10 x 8 mm rectangle (SIGSEGV in the 2-D meshing; transfinite
      // surfaces do not use the algorithm), tests/solver/test_formability_output.cpp's blank.
      gmsh::option::setNumber("Mesh.Algorithm", 6);
    }
    gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
    gmsh::model::mesh::generate(2);
  });
}

void mesh_curves(const GmshJob& job, MeshFormat format) {
  run_gmsh_step(job.file, "meshing in 1-D", [&] {
    set_sizes(job, format);
    gmsh::model::mesh::generate(1);
  });
}

// A part of surfaces: meshed in 2-D (a .geo or CAD file; the element count checked first), an
// imported file's surfaces made its group.
void make_surfaces(const GmshJob& job, MeshFormat format, const SandboxReporter& reporter) {
  if (is_meshed(format) && job.element_size > 0.0) {
    check_element_count(job, reporter);
  }
  if (is_meshed(format)) {
    mesh_surfaces(job, format);
  }
  if (is_imported(format)) {
    run_gmsh_step(job.file, "forming the part's group",
                  [&] { group_imported_surfaces(job.file, job.import); });
  }
}

// A curve (a trim line): meshed in 1-D only, a few thousand points at most; a CAD file's curves
// made its group.
void make_curves(const GmshJob& job, MeshFormat format) {
  if (is_meshed(format)) {
    mesh_curves(job, format);
  }
  if (is_cad(format)) {
    run_gmsh_step(job.file, "forming the curve's group",
                  [&] { group_imported_curves(job.file, job.import); });
  }
}

// What the parent needs before any group is taken: nodes, and named parts.
void check_not_empty(const std::filesystem::path& file) {
  std::size_t nodes = 0;
  gmsh::vectorpair groups;
  run_gmsh_step(file, "reading the mesh", [&] {
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
    nodes = tags.size();
    gmsh::model::getPhysicalGroups(groups);
  });
  if (nodes == 0) {
    throw InputError(quoted(file) + ": the mesh is empty (gmsh made no nodes)");
  }
  if (groups.empty()) {
    throw InputError(quoted(file) +
                     ": no physical groups (name the parts, e.g. Physical Surface(\"blank\") = "
                     "{1};)");
  }
}

void write_mesh(const GmshJob& job, const std::filesystem::path& scratch) {
  run_gmsh_step(job.file, "writing the mesh", [&] {
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::option::setNumber("Mesh.SaveParametric", 0);
    gmsh::option::setNumber("Mesh.Binary", 1);
    gmsh::write((scratch / GmshJobFiles::mesh).string());
    if (job.ascii_copy) {
      gmsh::option::setNumber("Mesh.Binary", 0);
      gmsh::write((scratch / GmshJobFiles::ascii_mesh).string());
    }
  });
}

void write_error(const std::filesystem::path& scratch, const std::string& kind,
                 const std::string& message) {
  std::ofstream out(scratch / GmshJobFiles::error, std::ios::binary);
  out << kind << '\n' << message;
}

}  // namespace

int run_gmsh_job(const GmshJob& job, const std::filesystem::path& scratch,
                 const SandboxReporter& reporter) {
  try {
    const MeshFormat format = mesh_format(job.file);
    reporter.report(GmshJobStage::reading);
    check_file_is_whole(job.file, format);
    GmshSession session;
    open_file(job, format, scratch);
    if (job.import.curves_only) {
      make_curves(job, format);
    } else {
      make_surfaces(job, format, reporter);
    }
    check_not_empty(job.file);
    reporter.report(GmshJobStage::writing);
    write_mesh(job, scratch);
    return 0;
  } catch (const GeoParameterError& e) {
    write_error(scratch, fmt::format("parameter {}", e.index()), e.what());
  } catch (const InputError& e) {
    write_error(scratch, "input", e.what());
  } catch (const std::bad_alloc&) {
    write_error(scratch, "memory", "");
  }
  return 1;
}

}  // namespace sf
