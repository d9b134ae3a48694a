#pragma once
// The contact's result fields of a frame (docs/results-format.md): for every tool with a contact
// pair, the pressure on each blank node and the path the node has slid over the tool; and which
// tool presses each node hardest.
#include <vector>

#include "model/model.hpp"
#include "results/results_writer.hpp"
#include "solver/solution_state.hpp"

namespace sf {

class ContactFieldsOutput {
 public:
  /// Sizes the fields for the model's blank and pairs, and takes each node's area and half
  /// thickness at the start.
  void set_up(const Model& model);
  /// Fills the fields from the state and appends them to `fields`:
  ///  - contact_pressure_<tool> (MPa): the pair's normal force on the node over the node's area
  ///    now, its area at the start times its half thickness then over now (plastic flow keeps
  ///    the volume);
  ///  - sliding_distance_<tool> (mm): the path the node has slid over the tool;
  ///  - contact_tool (-): the index (in the case's [[tools]] order) of the tool pressing the node
  ///    hardest, -1 where none does.
  /// Nothing for a model without contact pairs. The views point into this object and the
  /// state: valid until the next call.
  void add_fields(const Model& model, const SolutionState& s, std::vector<FieldView>& fields);

 private:
  VectorX start_area_;             ///< mm^2 per node
  VectorX start_half_thickness_;   ///< mm per node
  std::vector<VectorX> pressure_;  ///< MPa per node, one per pair
  VectorX contact_tool_;           ///< per node
  VectorX strongest_;              ///< N per node: the largest normal force met (scratch)
  VectorX zeros_;                  ///< a pair's sliding distances before its first call
};

}  // namespace sf
