#include "solver/formability_output.hpp"

#include <algorithm>
#include <cmath>

#include "element/element_block.hpp"
#include "element/shell_surface_strain.hpp"
#include "model/blank_parts.hpp"

namespace sf {

namespace {

constexpr std::array<double, 3> kZeta = {-1.0, 0.0, 1.0};  // bottom, mid, top
using Surface = FormabilityConfig::Surface;

// The surface whose strains judge the element: the one asked for, or with the least margin.
int judged_surface(Surface surface, const std::array<double, 3>& margin) {
  switch (surface) {
    case Surface::bottom:
      return 0;
    case Surface::mid:
      return 1;
    case Surface::top:
      return 2;
    case Surface::worst:
      break;
  }
  int worst = 1;
  for (int k : {0, 2}) {
    if (margin[static_cast<std::size_t>(k)] < margin[static_cast<std::size_t>(worst)]) {
      worst = k;
    }
  }
  return worst;
}

}  // namespace

FormabilityEvaluator::FormabilityEvaluator(const Model& model)
    : reference_normals_(nodal_unit_normals(model.blank.part.quads, model.blank.part.triangles,
                                            model.blank.mesh.nodes)),
      initial_thickness_(element_thicknesses(model.blank)) {
  const int n = element_count(model.blank.part);
  curve_of_.resize(static_cast<std::size_t>(n));
  for (int e = 0; e < n; ++e) {
    curve_of_[static_cast<std::size_t>(e)] = &model.formability.part_curves.at(
        static_cast<std::size_t>(material_index(model.blank.part, e)));
  }
}

void FormabilityEvaluator::evaluate(const Model& model, const Matrix3X& x,
                                    const std::vector<double>& thickness,
                                    FormabilityFields& out) const {
  const ShellPart& part = model.blank.part;
  const ElementBlocks blocks = element_blocks(part);
  const int n = element_count(part);
  for (int k = 0; k < 3; ++k) {
    out.major[static_cast<std::size_t>(k)].resize(n);
    out.minor[static_cast<std::size_t>(k)].resize(n);
  }
  out.thinning_percent.resize(n);
  out.flc_margin.resize(n);
  out.zone.resize(n);
  out.wrinkle_indicator.resize(n);
  const Matrix3X normals = nodal_unit_normals(part.quads, part.triangles, x);
  const FormabilityConfig& thresholds = model.formability.thresholds;
  std::array<Vec3, 4> X, xs, N, ns;
  for (int e = 0; e < n; ++e) {
    const ElementBlock& block = blocks.of(e);
    const auto corners = static_cast<std::size_t>(block.nodes_per_element());
    for (std::size_t a = 0; a < corners; ++a) {
      const int i = block.element_nodes(e)[a];
      X[a] = model.blank.mesh.nodes.col(i);
      xs[a] = x.col(i);
      N[a] = reference_normals_.col(i);
      ns[a] = normals.col(i);
    }
    const ElementCorners c{
        {X.data(), corners}, {xs.data(), corners}, {N.data(), corners}, {ns.data(), corners}};
    const auto ue = static_cast<std::size_t>(e);
    const double t0 = initial_thickness_[ue];
    const double t = thickness[ue];
    const FormingLimitCurve& curve = *curve_of_[ue];
    std::array<double, 3> margin{};
    for (std::size_t k = 0; k < 3; ++k) {
      const PrincipalStrains p = surface_principal_strains(c, kZeta[k], t0, t);
      out.major[k][e] = p.major;
      out.minor[k][e] = p.minor;
      margin[k] = flc_margin(curve, p.major, p.minor);
    }
    const auto k = static_cast<std::size_t>(judged_surface(thresholds.surface, margin));
    const double major = out.major[k][e];
    const double minor = out.minor[k][e];
    out.thinning_percent[e] = 100.0 * (1.0 - t / t0);
    out.flc_margin[e] = margin[k];
    out.zone[e] = static_cast<double>(
        formability_zone(major, minor, margin[k], out.thinning_percent[e], thresholds));
    out.wrinkle_indicator[e] = std::max(0.0, -(major + minor));
  }
}

void FormabilityFieldsOutput::set_up(const Model& model) {
  evaluator_.emplace(model);
}

void FormabilityFieldsOutput::add_fields(const Model& model, const Matrix3X& x,
                                         const std::vector<double>& thickness,
                                         std::vector<FieldView>& fields) {
  evaluator_->evaluate(model, x, thickness, fields_);
  constexpr std::array<const char*, 3> kSurface = {"bottom", "mid", "top"};
  for (std::size_t k = 0; k < 3; ++k) {
    fields.push_back({std::string("major_strain_") + kSurface[k], FieldCenter::cell, 1,
                      fields_.major[k].data()});
    fields.push_back({std::string("minor_strain_") + kSurface[k], FieldCenter::cell, 1,
                      fields_.minor[k].data()});
  }
  fields.push_back({"thinning_percent", FieldCenter::cell, 1, fields_.thinning_percent.data()});
  fields.push_back({"flc_margin", FieldCenter::cell, 1, fields_.flc_margin.data()});
  fields.push_back({"formability_zone", FieldCenter::cell, 1, fields_.zone.data()});
  fields.push_back({"wrinkle_indicator", FieldCenter::cell, 1, fields_.wrinkle_indicator.data()});
}

}  // namespace sf
