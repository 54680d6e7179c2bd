#pragma once
// The pictures `cosmos inspect` writes for a person to look at.
#include <filesystem>

#include "core/range_image.hpp"
#include "core/representation/cosmos_pipeline.hpp"

namespace cosmos {

// Writes range.png, shape_index.png, csmps.png, gauss_map.png and spectrum.png into dir.
void write_view_pictures(const RangeImage& image, const ViewAnalysis& analysis,
                         const std::filesystem::path& dir);

}  // namespace cosmos
