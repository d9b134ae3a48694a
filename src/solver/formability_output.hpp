#pragma once
// The formability result fields of a frame (docs/formability.md, docs/results-format.md): per
// blank element, the major and minor true strains of its bottom, mid and top surfaces, its
// thinning, its margin to its part's forming limit curve, its zone of the forming limit diagram
// and a wrinkle indicator. Computed from the shape (element/shell_surface_strain.hpp) when a
// frame is written; frames are rare, so this is off the hot path.
#include <array>
#include <optional>
#include <vector>

#include "model/model.hpp"
#include "results/results_writer.hpp"

namespace sf {

/// The fields, one value per element (cell order: quadrilaterals, then triangles).
struct FormabilityFields {
  /// -, true strains of the surfaces: [0] bottom (zeta = -1), [1] mid, [2] top (zeta = +1)
  std::array<VectorX, 3> major, minor;
  VectorX thinning_percent;   ///< 100 (1 - t / t0), per cent
  VectorX flc_margin;         ///< -, FLC major at the minor strain minus the major; NaN: no FLC
  VectorX zone;               ///< FormabilityZone as a number (0 safe ... 5 cracks)
  VectorX wrinkle_indicator;  ///< -, max(0, -(major + minor)): minor compression beyond major
};

class FormabilityEvaluator {
 public:
  /// Takes the blank's reference shape, normals and thicknesses and each element's curve.
  explicit FormabilityEvaluator(const Model& model);
  /// The fields of the blank at positions x (mm, per node) and thicknesses (mm, per element).
  void evaluate(const Model& model, const Matrix3X& x, const std::vector<double>& thickness,
                FormabilityFields& out) const;

 private:
  Matrix3X reference_normals_;                      ///< unit, per node
  std::vector<double> initial_thickness_;           ///< mm, per element
  std::vector<const FormingLimitCurve*> curve_of_;  ///< per element, into the model's plan
};

class FormabilityFieldsOutput {
 public:
  void set_up(const Model& model);
  /// Fills the fields from the blank's positions and thicknesses and appends them to `fields`
  /// (major_strain_bottom / _mid / _top, minor_strain_*, thinning_percent, flc_margin,
  /// formability_zone, wrinkle_indicator). The views point into this object: valid until the
  /// next call.
  void add_fields(const Model& model, const Matrix3X& x, const std::vector<double>& thickness,
                  std::vector<FieldView>& fields);

 private:
  std::optional<FormabilityEvaluator> evaluator_;  ///< once set up
  FormabilityFields fields_;
};

}  // namespace sf
