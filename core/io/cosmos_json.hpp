#pragma once
// cosmos.json of `cosmos inspect`; its keys are a stable contract read by regression suites:
// patches: [{id, area_mm2, shape_index, shape_index_min, shape_index_max, curvedness,
//            normal: [x,y,z], centroid_mm: [x,y,z], pixels, planar, neighbors: [id,...]}],
// spectrum: {bin_width, bins: [...], planar_fraction}, moments: [m1..m10], valid_pixels.
#include <filesystem>
#include <string>

#include "core/representation/cosmos_pipeline.hpp"

namespace cosmos {

std::string cosmos_json_text(const ViewAnalysis& analysis);
void write_cosmos_json(const ViewAnalysis& analysis, const std::filesystem::path& path);

}  // namespace cosmos
