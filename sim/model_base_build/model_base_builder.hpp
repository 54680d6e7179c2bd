#pragma once
// Builds the model base (ch. 4, Fig. 5.3) from the part catalog: every part seen from the view
// directions of §4.5 through sim's ModelViewRenderer (the simulated scanner, profile mode) and
// the same COSMOS code as live scans (analyze_view, build_registration_points), then each
// part's views grouped into clusters (§4.4.2), its whole surface summarized for the pose
// search (core/modelbase/part_surface_summary.hpp), and the parts it may be taken for listed
// (core/recognition/confusable_parts.hpp).
//
// Parallel and deterministic: worker threads pull (part, view) jobs from an atomic counter,
// each result lands in its job's slot, and everything after (grouping, the file) runs in job
// order, so the base is byte-identical for any thread count.
#include <functional>

#include "core/cosmos_parameters.hpp"
#include "core/modelbase/model_base.hpp"
#include "core/modelbase/view_grouping.hpp"
#include "core/recognition/confusable_parts.hpp"
#include "core/registration/part_surface_voxels.hpp"
#include "core/registration/registration_points.hpp"
#include "scanner/conditioning_parameters.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/model_base_build/view_direction_subset.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_pose.hpp"

namespace cosmos {

// The model surface's control points (ch. 6): every 3rd pixel of the 0.4 mm scans, i.e.
// 1.2 mm apart, each with its own quadric over a 5 x 5 (1.6 mm) window. The blended model
// surface stays well below the 0.02 mm sensor noise from the noise-free surface at strides 2
// and 3, and hardly closer at 2; at stride 4 its error grows markedly on the curved parts
// and it loses more surface near holes and borders. Memory decides between 2 and 3: stride 2
// has about twice the points of stride 3, which would take a full base of 20 parts x 320
// views over the 512 MB a loaded base may take (BM_LoadModelBase of
// bench/model_base_file_bench.cpp reports the file and resident sizes at both strides'
// point counts).
RegistrationPointParameters model_surface_registration_parameters();

struct ModelBaseBuildSettings {
  int view_count = kFullViewCount;  // the first N of spread_view_subset
  int threads = 0;                  // 0: every core
  // The one default construction of a cell's COSMOS parameters: the base records them and
  // every recognizer of its scans takes them from there.
  CosmosParameters cosmos;
  RegistrationPointParameters registration = model_surface_registration_parameters();
  ViewGroupingParameters grouping;
  // The cell's conditioning: the model views lose the belt at its height_threshold_mm, as
  // live scans do (the views' grid is the scanner's samples and profiles, recorded beside it).
  ConditioningParameters conditioning;
  // The stable poses each part's record holds (sim/part_pose.hpp).
  RestingPoseParameters resting;
  // The voxels of each part's surface, from which a recognizer builds the part's distance
  // field (core/modelbase/part_surface_summary.hpp).
  PartDistanceFieldParameters field;
  // Which parts each part may be taken for, from every part's quick field fits to a few views of
  // every other (core/recognition/confusable_parts.hpp).
  ConfusablePartParameters confusion;
};

struct ModelBaseBuildProgress {
  int views_done = 0;
  int views_total = 0;
  int parts_done = 0;  // parts [0, parts_done) have all their views
  int parts_total = 0;
};
// Called on the calling thread, about ten times a second and whenever parts_done grows.
using ModelBaseProgress = std::function<void(const ModelBaseBuildProgress&)>;

// Meshes that do not load throw InputError naming the file. Views in which the scanner
// measured nothing (a part outside the measuring range from that side) are left out.
ModelBase build_model_base(const PartCatalog& catalog, const ScannerParameters& scanner,
                           const ModelBaseBuildSettings& settings,
                           const ModelBaseProgress& progress = {});

}  // namespace cosmos
