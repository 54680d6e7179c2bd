#pragma once
// The first merges of constrained region growing (§3.5.2), done in one raster pass: each pixel
// joins the seeds of its already visited neighbours, the one giving the least joined S_I range
// first, while a seed's range stays within seed_shape_index_quantum. The priority-queue growth
// then continues from the seeds over their adjacency: a view has far fewer seeds than pixels
// and seed pairs than pixel pairs (bench/cosmos_pipeline_bench.cpp reports both counts), so
// the queue holds a fraction of the work. Growing from single pixels merged such near-equal
// pairs first anyway, through the queue; the raster pass spares the queue that work.
#include <cstdint>
#include <utility>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/surface/darboux_frame_field.hpp"
#include "core/surface/shape_index.hpp"

namespace cosmos {

struct ShapeSeeds {
  std::vector<std::int32_t> seed_of_pixel;  // seed id, in raster order of first pixel; -1 none
  std::vector<float> shape_index_min;       // per seed
  std::vector<float> shape_index_max;
  std::vector<float> area_mm2;
  std::vector<double> shape_area;  // sum of S_I * area, for mean shape indices
  // Seed pairs joined by at least one growing edge, in raster order of their last such edge
  // (the growing queue pops the last filed edge of a bucket first). A pair repeats only when
  // the table of recently listed pairs lost it, which on real views is rare (the segmentation
  // bench reports the listed and the different pairs).
  std::vector<std::pair<std::int32_t, std::int32_t>> adjacent;

  int seed_count() const { return static_cast<int>(area_mm2.size()); }
};

// Growing edges join 8-adjacent region pixels on the same side of any depth jump with the same
// label; planar pixels only when their normals agree within parameters.planar_crease_deg.
ShapeSeeds find_shape_seeds(const DarbouxFrameField& frames, const ShapeIndexField& field,
                            const SegmentationParameters& parameters);

}  // namespace cosmos
