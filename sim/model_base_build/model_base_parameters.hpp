#pragma once
// The canonical parameters text of a model base (core/io/parameters_text.hpp): every parameter
// that shapes its views, COSMOS and clusters, written by visiting the parameter structs
// (core/parameter_visitor.hpp), so a field added to one of them is in the text without another
// line here. A cell takes its COSMOS parameters from it (core/io/recorded_parameters.hpp) and
// refuses a base whose views were taken on another grid (scanner/model_view_conditioning.hpp),
// and `modelbase info` shows it.
//
// Keys: cosmos.* (CosmosParameters), registration.* (the model surface's control points),
// scanner.* (the simulated scanner that took the model views), conditioning.* (the views'
// grid and belt threshold, ModelViewConditioning), views.* (how many, which directions),
// grouping.* (the dendrogram cut), resting.* (the parts' stable poses), field.* (the voxels of
// each part's surface), confusion.* (the fits that list each part's confusable parts). Left
// out on purpose: the scanner's camera-frame drawing
// (model views are scanned in profile mode, which never draws frames) and its line rate (it
// paces the belt in time, not in space).
#include <string>

#include "scanner/model_view_conditioning.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/model_base_build/model_base_builder.hpp"

namespace cosmos {

std::string model_base_parameters_text(const ScannerParameters& scanner,
                                       const ModelBaseBuildSettings& settings);

}  // namespace cosmos
