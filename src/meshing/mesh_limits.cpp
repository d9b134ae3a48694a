#include "meshing/mesh_limits.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>

#include "meshing/gmsh_job.hpp"

namespace sf {

MeshTimeLimit::MeshTimeLimit(const MeshLimits& limits, double file_bytes)
    : limits_(limits), file_bytes_(file_bytes), start_(std::chrono::steady_clock::now()) {}

double MeshTimeLimit::read_seconds() const {
  return kReadSeconds + kReadSecondsPerMB * file_bytes_ / 1e6;
}

double MeshTimeLimit::mesh_seconds(double elements) const {
  return kMeshSeconds + kMeshSecondsPerElement * std::clamp(elements, 0.0, limits_.max_elements);
}

double MeshTimeLimit::seconds_for(const std::string& report) {
  const std::string estimate = std::string(GmshJobStage::estimate) + " ";
  if (report.rfind(estimate, 0) == 0) {
    elements_ = std::strtod(report.c_str() + estimate.size(), nullptr);
  }
  if (limits_.seconds > 0.0) {
    const double used =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return std::max(limits_.seconds - used, 1e-3);
  }
  return elements_ >= 0.0 ? mesh_seconds(elements_) : read_seconds();
}

double MeshTimeLimit::cpu_seconds() const {
  if (limits_.seconds > 0.0) {
    return limits_.seconds + 1.0;  // the wall-clock deadline acts first
  }
  return read_seconds() + mesh_seconds(limits_.max_elements) + 1.0;
}

std::string MeshTimeLimit::explain(const std::string& last_report, double deadline) const {
  const bool meshing = elements_ >= 0.0;
  const std::string stage = last_report == GmshJobStage::writing ? "writing the mesh"
                            : meshing                            ? "meshing"
                                                                 : "reading";
  if (limits_.seconds > 0.0) {
    return fmt::format(
        "gmsh did not finish reading and meshing it within {:g} s (limits.mesh_seconds; stopped "
        "while {}); a loop without end, or far too fine a mesh? Raise limits.mesh_seconds for a "
        "mesh that needs longer",
        limits_.seconds, stage);
  }
  if (meshing) {
    return fmt::format(
        "gmsh did not finish meshing it within {:.0f} s, the time allowed for about {:.2g} "
        "elements ({:g} s + {:g} s per element); far too fine a mesh, or gmsh stuck on this "
        "geometry? Set limits.mesh_seconds to give it longer",
        deadline, elements_, kMeshSeconds, kMeshSecondsPerElement);
  }
  return fmt::format(
      "gmsh did not finish reading it within {:.0f} s ({:g} s + {:g} s per MB of the file) and "
      "had produced nothing; a .geo loop without end, or a damaged file? Set "
      "limits.mesh_seconds to give it longer",
      deadline, kReadSeconds, kReadSecondsPerMB);
}

}  // namespace sf
