#pragma once
// Constant-shape maximal patches by constrained region growing (§3.5.2), with the adaptive
// shape-diameter limit of §5.4.3: seeds (shape_seeds.hpp) grown least merged diameter first
// over their adjacency (region_merge_queue.hpp), tiny patches folded into their most similar
// neighbour (tiny_patch_folding.hpp), boundary pixels moved to the nearer patch.
#include <cstdint>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/pixel_grid.hpp"
#include "core/segmentation/shape_seeds.hpp"
#include "core/surface/darboux_frame_field.hpp"
#include "core/surface/shape_index.hpp"

namespace cosmos {

inline constexpr std::int32_t kNoPatch = -1;

struct CsmpSegmentation {
  PixelGrid<std::int32_t> patch_of_pixel;  // patch id in [0, patch_count) or kNoPatch
  int patch_count = 0;
  double shape_diameter_limit = 0;  // the limit that was used (adaptive or fixed)
};

// `frames` supplies the normals that keep differently oriented planar faces apart.
CsmpSegmentation segment_csmps(const DarbouxFrameField& frames, const ShapeIndexField& field,
                               const SegmentationParameters& parameters);
// The same from the field's seeds (find_shape_seeds, or the real-time part builder's, found
// row by row as its rows arrived): growing, folding and refinement.
CsmpSegmentation segment_csmps_from_seeds(const ShapeIndexField& field, const ShapeSeeds& seeds,
                                          const SegmentationParameters& parameters);

// Boundary refinement can hand every pixel of a small patch to its neighbours: segment_csmps
// drops the emptied ids, the others keeping their order (that of their first pixels), so that
// every patch of a view has a surface to describe (§3.5).
void drop_emptied_patches(CsmpSegmentation& segmentation);

}  // namespace cosmos
