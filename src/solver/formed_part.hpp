#pragma once
// The formed part: the blank as it stands at the end of an operation, as one HDF5 file that the
// next operation or another case starts from (issue 32, item 1; docs/process-chain.md). It holds
// the blank's reference mesh (nodes, quads, triangles, node groups), its through-thickness rule
// and material law, and every state field with the formed-part role (solver/state_fields.hpp):
// coordinates, velocities, forces, masses, thickness, per-point stresses, plastic strains, flow
// and back stresses, and the tools' positions. Format version 3 (2 added the tools' turns, 3 the
// blank's parts); a reader reads 1 to 3 and refuses another.
//
// Layout: attributes /@format = "sheetform formed part", /@format_version, /@git_hash,
// /@units; /mesh/reference_nodes (n, 3), /mesh/node_tags (n), /mesh/quads (q, 4) and
// /mesh/triangles (t, 3) as 0-based node indices, /mesh/initial_thickness (per element, mm),
// /mesh/groups/NAME (node indices); for a blank of several parts (a tailor-welded blank)
// /mesh/element_part (per element, an index into the parts) and /mesh/parts/P@name;
// /section@n_points, @rule; /material@law; /state/KEY (a field's values: per node (n, 3) or
// (n), per element or point (elements, values per element), run numbers (1)), each with
// attributes place and unit; /state/tools/T@name, /state/contacts/C@tool (its tool's name).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "model/build_model.hpp"
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// The formed-part file of a results folder.
inline std::filesystem::path formed_part_path(const std::filesystem::path& results_folder) {
  return results_folder / "formed_part.h5";
}

/// The formed part at the end of operation `name` of the press line (results folder).
inline std::filesystem::path operation_formed_part_path(const std::filesystem::path& results_folder,
                                                        const std::string& name) {
  return results_folder / ("formed_part." + name + ".h5");
}

/// Whether `file` is one of a run's formed parts (or its temporary): formed_part.h5,
/// formed_part.NAME.h5.
inline bool is_formed_part_file(const std::filesystem::path& file) {
  std::string name = file.filename().string();
  if (name.size() > 4 && name.ends_with(".tmp")) {
    name.resize(name.size() - 4);
  }
  return name.starts_with("formed_part.") && name.ends_with(".h5");
}

/// A formed part as read from its file.
struct FormedPart {
  std::string file;          ///< where it was read from (for messages)
  Matrix3X reference_nodes;  ///< mm, the blank's nodes at time 0 of the first operation
  std::vector<double> initial_thickness;  ///< mm per element, at time 0 of the first operation
  std::vector<double> node_tags;          ///< the mesh file's node numbers
  QuadConn quads;
  TriConn triangles;
  std::map<std::string, std::vector<int>> groups;  ///< node groups, by name
  /// A blank of several parts: their names, and each element's index into them (both empty for
  /// a blank of one part).
  std::vector<std::string> part_names;
  std::vector<int> element_part;
  int n_points = 0;  ///< through the thickness
  std::string rule;  ///< gauss or lobatto
  std::string law;   ///< the material law's kind (a blank of several parts: each part's, ", ")
  std::vector<std::string> tools;          ///< names, in the order of the state's tools
  std::vector<std::string> contact_tools;  ///< each contact pair's tool, in the state's order
  /// Every state field by key (state_fields.hpp), flat, in the state's memory order.
  std::map<std::string, std::vector<double>> fields;
};

/// Writes `file` (atomically: a temporary file renamed) from the model and the state (the whole
/// state: in a distributed run, gathered to this process first). Throws OutputError naming the
/// file when it cannot be written.
void write_formed_part(const std::filesystem::path& file, const Model& model,
                       const SolutionState& state);

/// Writes `file` from a part held in memory (a trimmed part, solver/trim.hpp): its mesh and
/// fields, with the formed-part fields it lacks (those the next model makes again from the mesh:
/// forces, masses, offsets, contact pairs' history) listed in the attribute left_out of /state,
/// which read_formed_part accepts. Throws OutputError naming the file.
void write_formed_part(const std::filesystem::path& file, const FormedPart& part);

/// The part's mesh and node groups, for build_model to build a model on (after a trim, or for a
/// case whose blank is a formed part's own mesh).
BlankMesh blank_mesh_of(const FormedPart& part);

/// Reads `file`; throws InputError naming the file and the entry when it is not a formed part,
/// of another format version, or damaged.
FormedPart read_formed_part(const std::filesystem::path& file);

/// Puts the formed part's state into `state`, a state of `model` (make_initial_state): the
/// model's blank must be the part's (the same reference mesh, through-thickness rule and
/// law, else InputError naming what differs). A tool of the model takes the state of the
/// part's tool of the same name (where the first case left it), and a contact pair with such a
/// tool the stick forces of the part's pair with it; the others keep theirs. Returns the names
/// of the tools that were placed so.
std::vector<std::string> apply_formed_part(const FormedPart& part, const Model& model,
                                           SolutionState& state);

/// The kind of the model's material law, as the formed part records it.
std::string material_law_kind(const Material& material);
/// The kinds of the part's materials, one per material in order, joined by ", ".
std::string material_law_kinds(const ShellPart& part);

}  // namespace sf
