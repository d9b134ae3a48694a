#pragma once
// The model: everything the time loop needs, built once from the case and the meshes by
// build_model (the one place that sees both).
#include <memory>
#include <string>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "element/shell_bt.hpp"
#include "io/case_config.hpp"
#include "mesh/mesh_data.hpp"
#include "mesh/triangle_surface.hpp"
#include "model/boundary_conditions.hpp"
#include "model/rigid_tool_motion.hpp"

namespace sf {

/// The deformable blank: mesh, element description, mass and named node groups.
struct Blank {
  PartMesh mesh;
  ShellPart part;
  VectorX mass;                   ///< tonne per node (after any mass scaling)
  VectorX rotational_inertia;     ///< tonne mm^2 per node
  double physical_mass = 0.0;     ///< tonne, before mass scaling
  double added_mass = 0.0;        ///< tonne, added by mass scaling
  VectorX inverse_element_count;  ///< per node, 1 / (elements sharing it), for nodal averages
  std::vector<NodeGroup> groups;  ///< the boundary groups and measurement points the case names
};

/// A rigid tool: its triangulated surface in the reference position and its prescribed motion.
struct Tool {
  std::string name;
  PartMesh mesh;  ///< as read (for output)
  TriangleSurface surface;
  RigidToolMotion motion;
};

/// A contact pair between all blank nodes and one tool's triangles.
struct ContactInterface {
  int tool = -1;  ///< index into Model::tools
  ContactPair pair;
};

struct Model {
  CaseConfig config;
  Blank blank;
  std::vector<Tool> tools;
  std::vector<ContactInterface> contacts;
  NodalConstraints constraints;
  double end_time = 0.0;   ///< s, from control.end_time or the stroke
  int stroke_tool = -1;    ///< index of the tool whose travel is the stroke, or -1
  double time_step = 0.0;  ///< s, the initial stable step with the safety factor (after scaling)
  int limiting_element = -1;
};

}  // namespace sf
