#pragma once
// The first merges of constrained region growing (§3.5.2), done as connected components: pixels
// joined by a growing edge whose shape indices fall in the same quantum of S_I can only ever
// form a patch of diameter below that quantum, so they start growing as one seed region. The
// priority-queue growth then continues from the seeds over their adjacency, which is a
// fraction of the pixel adjacency (most pixel pairs lie inside a seed).
#include <cstdint>
#include <utility>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/darboux_frame_field.hpp"
#include "core/shape_index.hpp"

namespace cosmos {

struct ShapeSeeds {
  std::vector<std::int32_t> seed_of_pixel;  // seed id, in raster order of first pixel; -1 none
  std::vector<float> shape_index_min;       // per seed
  std::vector<float> shape_index_max;
  std::vector<float> area_mm2;
  std::vector<double> shape_area;  // sum of S_I * area, for mean shape indices
  // Seed pairs joined by at least one growing edge, in raster order of that edge; a pair may
  // repeat (runs of the same pair along a boundary are listed once).
  std::vector<std::pair<std::int32_t, std::int32_t>> adjacent;

  int seed_count() const { return static_cast<int>(area_mm2.size()); }
};

// Growing edges join 8-adjacent region pixels on the same side of any depth jump with the same
// label; planar pixels only when their normals agree within parameters.planar_crease_deg.
ShapeSeeds find_shape_seeds(const DarbouxFrameField& frames, const ShapeIndexField& field,
                            const SegmentationParameters& parameters);

}  // namespace cosmos
