#include "core/matching/correspondence_goodness.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {
namespace {

// §5.3.3 area-goodness form: 1 when equal, towards 0 as they diverge; 1 for two zeros.
double ratio_goodness(double a, double b, double floor = 0.0) {
  const double sum = a + b + floor;
  return sum > 0 ? 1.0 - std::abs(a - b) / sum : 1.0;
}

double shape_similarity(const GroupSummary& a, const GroupSummary& b, double shape_index_scale) {
  const double planar_agreement = 1.0 - std::abs(a.planar_fraction - b.planar_fraction);
  const bool both_curved = a.planar_fraction < 1.0 && b.planar_fraction < 1.0;
  const double closeness =
      both_curved ? std::max(0.0, 1.0 - std::abs(a.shape_index - b.shape_index) / shape_index_scale)
                  : 1.0;
  return planar_agreement * closeness;
}

}  // namespace

GroupDescriptor describe_group(const PatchGraph& graph, PatchSet group) {
  GroupDescriptor descriptor;
  descriptor.group = summarize_group(graph, group);
  const PatchSet ring = adjacent_patches(graph, group);
  descriptor.neighbors = summarize_group(graph, ring);
  descriptor.neighbor_patches = patch_count(ring);
  return descriptor;
}

PairGoodness evaluate_pair(const GroupDescriptor& scene, const GroupDescriptor& model,
                           const GoodnessParameters& parameters) {
  PairGoodness g;
  g.area = ratio_goodness(scene.group.area_fraction, model.group.area_fraction);
  g.shape_index = shape_similarity(scene.group, model.group, parameters.shape_index_scale);
  g.curvedness = ratio_goodness(scene.group.curvedness_per_mm, model.group.curvedness_per_mm,
                                parameters.curvedness_floor_per_mm);
  const double neighbor_count = ratio_goodness(scene.neighbor_patches, model.neighbor_patches);
  // With no neighbours on one side there is no mean S_I to compare; the count term has
  // already scored that as 0.
  const bool both_have_neighbors = scene.neighbor_patches > 0 && model.neighbor_patches > 0;
  const double neighbor_shape =
      both_have_neighbors
          ? shape_similarity(scene.neighbors, model.neighbors, parameters.shape_index_scale)
          : 1.0;
  g.neighbor = neighbor_count * neighbor_shape;
  g.goodness = g.area * g.shape_index * g.curvedness * g.neighbor;
  g.fineness = std::sqrt(scene.group.largest_patch_fraction * model.group.largest_patch_fraction);
  g.weight = 0.5 * (scene.group.area_fraction + model.group.area_fraction);
  g.score = g.goodness * coarseness_factor(scene.group, model.group, parameters);
  return g;
}

double coarseness_factor(const GroupSummary& scene, const GroupSummary& model,
                         const GoodnessParameters& parameters) {
  const double fineness = std::sqrt(scene.largest_patch_fraction * model.largest_patch_fraction);
  // The exponent is 1 by default: skip the pow, which would dominate the matching time.
  return parameters.coarseness_exponent == 1.0 ? fineness
                                               : std::pow(fineness, parameters.coarseness_exponent);
}

bool planar_compatible(const GroupSummary& scene, const GroupSummary& model) {
  const bool scene_all_planar = scene.planar_fraction >= 1.0;
  const bool model_all_planar = model.planar_fraction >= 1.0;
  const bool scene_no_planar = scene.planar_fraction <= 0.0;
  const bool model_no_planar = model.planar_fraction <= 0.0;
  return !(scene_all_planar && model_no_planar) && !(model_all_planar && scene_no_planar);
}

double correspondence_quality(const PatchGraph& scene, const PatchGraph& model,
                              std::span<const GroupPair> pairs,
                              const GoodnessParameters& parameters) {
  double quality = 0;
  for (const GroupPair& pair : pairs) {
    const PairGoodness g = evaluate_pair(describe_group(scene, pair.scene),
                                         describe_group(model, pair.model), parameters);
    quality += g.weight * g.score;
  }
  return std::clamp(quality, 0.0, 1.0);
}

}  // namespace cosmos
