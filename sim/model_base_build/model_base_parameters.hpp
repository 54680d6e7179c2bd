#pragma once
// The canonical parameters text of a model base (core/io/parameters_text.hpp): every parameter
// that shapes its views, COSMOS and clusters, written by visiting the parameter structs
// (core/parameter_visitor.hpp), so a field added to one of them is in the text without another
// line here. A cell takes its COSMOS parameters from it and refuses a base whose views were
// taken on another grid, and `modelbase info` shows it.
//
// Keys: cosmos.* (CosmosParameters), registration.* (the model surface's control points),
// scanner.* (the simulated scanner that took the model views), conditioning.* (the views'
// grid and belt threshold, ModelViewConditioning), views.* (how many, which directions),
// grouping.* (the dendrogram cut). Left out on purpose: the scanner's camera-frame drawing
// (model views are scanned in profile mode, which never draws frames) and its line rate (it
// paces the belt in time, not in space).
#include <filesystem>
#include <optional>
#include <string>

#include "core/cosmos_parameters.hpp"
#include "core/io/parameters_text.hpp"
#include "core/modelbase/model_base.hpp"
#include "core/parameter_visitor.hpp"
#include "scanner/conditioning_parameters.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/model_base_build/model_base_builder.hpp"

namespace cosmos {

// What the model views' conditioning was: their pixel pitch across the belt (the scanner's
// sample spacing) and along it (its profile step), and the height below which the belt is
// background. A live scan is comparable only on the same grid with the same threshold.
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

std::string model_base_parameters_text(const ScannerParameters& scanner,
                                       const ModelBaseBuildSettings& settings);

// The COSMOS parameters the base was built with (its cosmos.* keys): what every analysis of
// a scene recognized against it must use. InputError naming `file` and the key when the base
// lacks one (a base older than the parameter: rebuild it).
CosmosParameters model_base_cosmos_parameters(const ModelBase& base,
                                              const std::filesystem::path& file);

// The conditioning its views were taken with (its conditioning.* keys); InputError as above.
ModelViewConditioning model_base_view_conditioning(const ModelBase& base,
                                                   const std::filesystem::path& file);

// The first conditioning.* key in which a base's views (`recorded`) differ from what a cell
// with `conditioning` scans (expected: the cell's; actual: the base's); nullopt when they agree.
std::optional<ParameterDifference> conditioning_difference(
    const ModelViewConditioning& recorded, const ConditioningParameters& conditioning);

}  // namespace cosmos
