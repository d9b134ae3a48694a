#include "solver/contact_output.hpp"

#include "mesh/nodal_area.hpp"
#include "model/blank_parts.hpp"

namespace sf {

void ContactFieldsOutput::set_up(const Model& model) {
  const Blank& blank = model.blank;
  start_area_ = nodal_tributary_area(blank.mesh.nodes, blank.mesh.quads, blank.mesh.triangles);
  start_half_thickness_ = initial_half_thickness(blank, model.initial);
  pressure_.assign(model.contacts.size(), VectorX::Zero(blank.mesh.nodes.cols()));
  contact_tool_ = VectorX::Constant(blank.mesh.nodes.cols(), -1.0);
  strongest_ = VectorX::Zero(blank.mesh.nodes.cols());
  zeros_ = VectorX::Zero(blank.mesh.nodes.cols());
}

void ContactFieldsOutput::add_fields(const Model& model, const SolutionState& s,
                                     std::vector<FieldView>& fields) {
  if (model.contacts.empty()) {
    return;  // no tools touch the blank: no contact fields
  }
  const Eigen::Index n = start_area_.size();
  contact_tool_.setConstant(-1.0);
  strongest_.setZero();
  for (std::size_t k = 0; k < model.contacts.size(); ++k) {
    const ContactState& c = s.contacts[k];
    VectorX& pressure = pressure_[k];
    const bool sized = c.normal_force.size() == n;  // before the first contact call: none
    for (Eigen::Index i = 0; i < n; ++i) {
      const double force = sized ? c.normal_force[i] : 0.0;
      const double h = s.half_thickness.size() == n ? s.half_thickness[i] : 0.0;
      const double area = area_now(start_area_[i], start_half_thickness_[i], h);
      pressure[i] = area > 0.0 ? force / area : 0.0;
      if (force > strongest_[i]) {
        strongest_[i] = force;
        contact_tool_[i] = model.contacts[k].tool;
      }
    }
    const std::string& tool = model.tools[static_cast<std::size_t>(model.contacts[k].tool)].name;
    fields.push_back({"contact_pressure_" + tool, FieldCenter::node, 1, pressure.data()});
    if (sized) {
      fields.push_back(
          {"sliding_distance_" + tool, FieldCenter::node, 1, c.sliding_distance.data()});
    } else {
      fields.push_back({"sliding_distance_" + tool, FieldCenter::node, 1, zeros_.data()});
    }
  }
  fields.push_back({"contact_tool", FieldCenter::node, 1, contact_tool_.data()});
}

}  // namespace sf
