#pragma once
// The parts of a blank of several (a tailor-welded blank): which elements each part holds.
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "mesh/mesh_data.hpp"
#include "meshing/gmsh_model.hpp"
#include "model/model.hpp"

namespace sf {

/// Sorts the blank's elements by part (stably, quads still before triangles) and returns each
/// element's part: an index into `parts`, whose groups are 2-D physical groups of `model`. The
/// parts' elements are then consecutive, so that the element loops take each part's material in
/// one run. InputError naming the case file `case_file` and the part's line for a group that is
/// missing or holds an element outside the blank, and naming the element for one that is in no
/// part or in two; InputError for parts that are not joined: two distinct nodes at one place
/// along the boundary between parts (a weld line meshed twice).
std::vector<int> sort_blank_by_part(const GmshModel& model,
                                    const std::vector<BlankPartConfig>& parts,
                                    const std::string& case_file, PartMesh& mesh);

/// Each element's part for a blank given with its parts' labels (a formed part's mesh, read from
/// `source`): `element_part` indexes `names`; the result indexes `parts`, the case's parts of
/// those names (in any order). Empty for a blank of one part (no names and no parts).
/// InputError naming the case file `case_file` and `source` when the case's parts are not the
/// formed part's: a name one has and the other not, or parts on one side only.
std::vector<int> parts_by_name(const std::vector<std::string>& names,
                               const std::vector<int>& element_part,
                               const std::vector<BlankPartConfig>& parts,
                               const std::string& case_file, const std::string& source);

/// Each element's initial thickness (mm): its part's.
std::vector<double> element_thicknesses(const Blank& blank);

/// The blank's stress-free state at the start: each element at its part's thickness
/// (initial.element_thickness, or initial.thickness everywhere), the materials' back stresses
/// sized. Directors are not set (initialize_directors).
ShellState make_blank_shell_state(const Blank& blank, const InitialConditions& initial);

/// Each blank node's half thickness at the start (mm, the contact offset): the mean of its
/// elements' half thicknesses (gather_half_thickness), or half initial.thickness everywhere for a
/// blank of one thickness.
VectorX initial_half_thickness(const Blank& blank, const InitialConditions& initial);

}  // namespace sf
