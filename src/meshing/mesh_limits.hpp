#pragma once
// What gmsh may spend on one part (the case's [limits]), and the time each stage of its work gets.
#include <chrono>
#include <string>

namespace sf {

struct MeshLimits {
  /// s of wall time to read and mesh one part; 0 = scaled with the job (MeshTimeLimit).
  double seconds = 0.0;
  double max_elements = 5e6;  ///< elements of one part, estimated before gmsh meshes it
  double memory_gb = 0.0;     ///< GB gmsh may allocate (address space); 0 = this machine's memory
};

/// The deadlines of a sandboxed gmsh job, stage by stage (meshing/gmsh_job.hpp's reports).
/// With MeshLimits::seconds = S > 0 the whole job gets S. With 0 (the default), each stage gets
/// what its size calls for, a generous multiple of what gmsh needs:
///   reading the file:        kReadSeconds + kReadSecondsPerMB per MB of the file;
///   meshing and writing:     kMeshSeconds + kMeshSecondsPerElement per estimated element
///                            (a file that is read, not meshed: the reading's time again).
/// So a .geo that loops without producing anything is stopped after about a minute, and a mesh
/// of five million elements still has hours.
class MeshTimeLimit {
 public:
  static constexpr double kReadSeconds = 60.0;
  static constexpr double kReadSecondsPerMB = 4.0;
  static constexpr double kMeshSeconds = 60.0;
  static constexpr double kMeshSecondsPerElement = 2e-3;

  MeshTimeLimit(const MeshLimits& limits, double file_bytes);

  /// The seconds the job may take from now: `report` is "" at the start, then each stage line.
  double seconds_for(const std::string& report);
  /// The CPU-time limit of the whole job (s): the largest any stage sequence can be given.
  double cpu_seconds() const;
  /// Why the job was stopped after `deadline` s in the stage `last_report` began, for messages.
  std::string explain(const std::string& last_report, double deadline) const;

 private:
  double read_seconds() const;
  double mesh_seconds(double elements) const;

  MeshLimits limits_;
  double file_bytes_;
  double elements_ = -1.0;  // the child's estimate, once reported
  std::chrono::steady_clock::time_point start_;
};

}  // namespace sf
