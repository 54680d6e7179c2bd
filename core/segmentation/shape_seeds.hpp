#pragma once
// The first merges of constrained region growing (§3.5.2), done in one raster pass: each pixel
// joins the seeds of its already visited neighbours, the one giving the least joined S_I range
// first, while a seed's range stays within seed_shape_index_quantum. The priority-queue growth
// then continues from the seeds over their adjacency: a view has far fewer seeds than pixels
// and seed pairs than pixel pairs (bench/cosmos_pipeline_bench.cpp reports both counts), so
// the queue holds a fraction of the work. Growing from single pixels merged such near-equal
// pairs first anyway, through the queue; the raster pass spares the queue that work.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/segmentation/seed_union_find.hpp"
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

// The cosine of parameters.planar_crease_deg, as backward_seed_edges takes it.
double seed_crease_cos(const SegmentationParameters& parameters);

// Pass 2 of the search, after pass 1 (seed_union_find.hpp) has run over every row of `field`:
// a root opens the next seed, with the S_I range pass 1 kept at it; any other pixel takes its
// parent's seed (the parent precedes it, so it is already numbered). Areas are summed pixel
// by pixel. `node_of(row, column)` is pass 1's node of a pixel of `field` with a label, its
// parent a raster index of `field`.
template <class NodeOf>
ShapeSeeds number_shape_seeds(const ShapeIndexField& field, NodeOf&& node_of) {
  ShapeSeeds seeds;
  std::vector<std::int32_t>& seed_of_pixel = seeds.seed_of_pixel;
  seed_of_pixel.assign(field.label.size(), kNotSeeded);
  for (int row = 0; row < field.height(); ++row) {
    const SurfaceLabel* label = field.label.row(row);
    const auto row_start = static_cast<std::int32_t>(row * field.width());
    for (int column = 0; column < field.width(); ++column) {
      if (label[column] == SurfaceLabel::kInvalid) continue;
      const SeedNode& node = node_of(row, column);
      const std::int32_t i = row_start + column;
      const float shape_index = field.shape_index[i], area_mm2 = field.area_mm2[i];
      if (node.parent == i) {
        seed_of_pixel[i] = seeds.seed_count();
        seeds.shape_index_min.push_back(node.low);
        seeds.shape_index_max.push_back(node.high);
        seeds.area_mm2.push_back(area_mm2);
        seeds.shape_area.push_back(static_cast<double>(shape_index) * area_mm2);
      } else {
        const std::int32_t seed = seed_of_pixel[node.parent];
        seed_of_pixel[i] = seed;
        seeds.area_mm2[seed] += area_mm2;
        seeds.shape_area[seed] += static_cast<double>(shape_index) * area_mm2;
      }
    }
  }
  return seeds;
}

// Pass 3: the seed pairs, from pass 1's crossings between different seeds. `crossings` names
// pixels of the seeds' field, in the order pass 1 found them, a crossing that repeats the one
// before it listed once.
void list_seed_pairs(std::span<const std::pair<std::int32_t, std::int32_t>> crossings,
                     ShapeSeeds& seeds);

}  // namespace cosmos
