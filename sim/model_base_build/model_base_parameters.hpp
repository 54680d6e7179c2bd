#pragma once
// The canonical parameters text of a model base (core/io/parameters_text.hpp): every parameter
// that shapes its views, COSMOS and clusters, so a recognizer can refuse a base built for
// another cell (read_model_base's expected_parameters_text) and `modelbase info` can show them.
//
// Keys: cosmos.* (CosmosParameters), registration.* (the model surface's control points),
// scanner.* (the simulated scanner that took the model views), views.* (how many, which
// directions), grouping.* (the dendrogram cut). Left out on purpose: the scanner's camera-frame
// drawing (model views are scanned in profile mode, which never draws frames) and its line
// rate (it paces the belt in time, not in space). A field added to one of these structs must
// be added here, or bases built with different values would pass as equal.
#include <filesystem>
#include <string>

#include "core/cosmos_parameters.hpp"
#include "core/modelbase/model_base.hpp"
#include "core/modelbase/view_grouping.hpp"
#include "core/registration/registration_points.hpp"
#include "scanner/scanner_model.hpp"

namespace cosmos {

std::string model_base_parameters_text(const CosmosParameters& cosmos,
                                       const ScannerParameters& scanner,
                                       const RegistrationPointParameters& registration,
                                       int view_count, const ViewGroupingParameters& grouping);

// Reads a model base for recognition with `cosmos`: live scans must be analyzed exactly as
// the model views were, so a base whose cosmos.* parameters differ is refused with one line
// naming the file and the first differing key (InputError), like any unreadable base.
ModelBase read_model_base_for(const std::filesystem::path& path, const CosmosParameters& cosmos);

}  // namespace cosmos
