#pragma once
// The key of a pair of CSMPs of one view (§3.2: each patch's shape index, mean normal G0
// (Eq. 3.7) and centroid; §5.3: patches matched with their neighbours), and the local frame
// the pair fixes. Shape index, the angle between the two mean normals and the distance between the
// two centroids do not change when the part moves, so a scene pair and the same pair in a model
// view share a key wherever the part lies; the two frames then give the pose that maps one
// onto the other, as geometric hashing and point-pair-feature voting do with points.
//
// A planar patch (§3.1.3, shape index undefined) has a shape bin of its own; the normals'
// angle and the centroids' distance still tell mechanical parts' faces apart. Patches smaller
// than min_patch_area_mm2 take no part: their normals and centroids are noise.
#include <array>
#include <optional>

#include "core/parameter_visitor.hpp"
#include "core/representation/cosmos_view.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

struct PatchPairKeyParameters {
  int shape_index_bins = 4;  // over [-1, 1]; planar patches are one more bin
  double normal_angle_bin_deg = 20.0;
  double centroid_distance_bin_mm = 8.0;
  int centroid_distance_bins = 40;  // pairs farther apart are not indexed
  double min_patch_area_mm2 = 25.0;
  // The frame's second axis is the centroids' offset across the first patch's normal: a pair
  // stacked along that normal has none.
  double min_lateral_offset_mm = 2.0;
  // true: only adjacent patches pair (§5.3 patch groups); false: every two patches of a view.
  bool adjacent_only = false;

  int angle_bins() const;
  int shape_bins() const { return shape_index_bins + 1; }
  // Keys are 0 .. key_count() - 1.
  int key_count() const;

  template <class Visitor>
  void visit(Visitor& v) {
    v("shape_index_bins", shape_index_bins, "shape index bins over [-1, 1]", Range{1, 64});
    v("normal_angle_bin_deg", normal_angle_bin_deg, "bin of the angle between the normals, deg",
      Range::above(0, 180));
    v("centroid_distance_bin_mm", centroid_distance_bin_mm,
      "bin of the distance between the centroids, mm", Range::above(0, 1e3));
    v("centroid_distance_bins", centroid_distance_bins, "pairs farther apart are not indexed",
      Range{1, 1000});
    v("min_patch_area_mm2", min_patch_area_mm2, "smaller patches form no pair, mm^2",
      Range{0, 1e6});
    v("min_lateral_offset_mm", min_lateral_offset_mm,
      "centroid offset across the first normal a pair needs, mm", Range{0, 1e3});
    v("adjacent_only", adjacent_only, "only adjacent patches pair; false: every two");
  }
};

// An ordered pair (a, b) in continuous bin coordinates, and its frame in the view: origin the
// centroids' midpoint, x the normal of a, y the offset to b's centroid across that normal.
struct PatchPairFeature {
  double shape_a = 0;  // bin coordinate; shape_index_bins (exactly) for a planar patch
  double shape_b = 0;
  double angle = 0;     // normals' angle / normal_angle_bin_deg
  double distance = 0;  // centroids' distance / centroid_distance_bin_mm
  RigidTransform T_view_pair;
};

// std::nullopt when a patch is too small, the pair too far apart or its frame degenerate.
std::optional<PatchPairFeature> patch_pair_feature(const Csmp& a, const Csmp& b,
                                                   const PatchPairKeyParameters& parameters);

// Calls pair(a, b) for every unordered pair of the view's patches that pair (adjacent ones
// unless parameters.adjacent_only is false), each once, a before b in patch order.
template <class PairFunction>
void for_each_patch_pair(const CosmosView& view, const PatchPairKeyParameters& parameters,
                         PairFunction&& pair) {
  const std::vector<Csmp>& patches = view.patches;
  for (const Csmp& a : patches) {
    if (!parameters.adjacent_only) {
      for (std::size_t b = static_cast<std::size_t>(a.id) + 1; b < patches.size(); ++b)
        pair(a, patches[b]);
      continue;
    }
    for (const PatchNeighbor& neighbor : a.neighbors)
      if (neighbor.patch > a.id) pair(a, patches[static_cast<std::size_t>(neighbor.patch)]);
  }
}

// The key of the bins the feature falls in.
int patch_pair_key(const PatchPairFeature& feature, const PatchPairKeyParameters& parameters);

// A scene pair's value near a bin edge may fall on the other side in the model view: the keys
// of its own bins and of the nearer neighbouring bin in each continuous coordinate (a planar
// patch's shape bin has none), at most 16. Returns how many of `keys` it filled.
inline constexpr int kMaxNearbyPatchPairKeys = 16;
int nearby_patch_pair_keys(const PatchPairFeature& feature,
                           const PatchPairKeyParameters& parameters,
                           std::array<int, kMaxNearbyPatchPairKeys>& keys);

}  // namespace cosmos
