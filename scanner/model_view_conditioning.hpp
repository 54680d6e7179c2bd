#pragma once
// What a model base's views were conditioned with, and whether a cell's scans are comparable:
// their pixel pitch across the belt (the scanner's sample spacing) and along it (its profile
// step), and the height below which the belt is background. The model-base build records it
// under conditioning.*; a cell refuses a base taken on another grid or threshold than its own
// conditioning gives its scans.
#include <filesystem>
#include <optional>

#include "core/io/parameters_text.hpp"
#include "core/modelbase/model_base.hpp"
#include "scanner/conditioning_parameters.hpp"
#include "scanner/scanner_model.hpp"

namespace cosmos {

struct ModelViewConditioning {
  double grid_x_mm = 0;
  double grid_y_mm = 0;
  double height_threshold_mm = 0;

  template <class Visitor>
  void visit(Visitor& v) {
    v("grid_x_mm", grid_x_mm, "pixel pitch across the belt, mm");
    v("grid_y_mm", grid_y_mm, "pixel pitch along the belt, mm");
    v("height_threshold_mm", height_threshold_mm, "belt threshold, mm");
  }
};

// Pitches are rounded to 1e-6 mm, so the same pitch computed two ways compares equal.
ModelViewConditioning model_view_conditioning(const ScannerParameters& scanner,
                                              const ConditioningParameters& conditioning);
// What a cell with `conditioning` gives its scans: grid_mm across and along the belt.
ModelViewConditioning live_scan_conditioning(const ConditioningParameters& conditioning);

// The conditioning a base's views were taken with (its conditioning.* keys); InputError
// naming `file` and the key when the base lacks one.
ModelViewConditioning model_base_view_conditioning(const ModelBase& base,
                                                   const std::filesystem::path& file);

// The first conditioning.* key in which a base's views (`recorded`) differ from what a cell
// with `conditioning` scans (expected: the cell's; actual: the base's); nullopt when they agree.
std::optional<ParameterDifference> conditioning_difference(
    const ModelViewConditioning& recorded, const ConditioningParameters& conditioning);

}  // namespace cosmos
