#pragma once
// Which pixels of a scene a recognized part explains, for scenes that hold several parts
// (parts touching on the belt, or too close to be told apart by the tracker): the thesis
// leaves several objects to future work, but its units make the step natural. A CSMP
// belongs to one part, and the patch groups one model view explains are taken away together
// (§5.3); what the recognized part covers of the others is occlusion (§7.2.5), which the
// next recognition, of what remains, tolerates like any self-occlusion. The part's whole
// surface is its distance field (the union of its views, part_distance_field.hpp): a pixel
// is explained when its point lies within distance_mm of it under the recognized pose.
#include <cstdint>
#include <vector>

#include "core/range_image.hpp"
#include "core/registration/part_distance_field.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

// 1 per pixel (row-major, the image's size) whose point lies within distance_mm of the
// part's surface placed at T_scene_part; 0 elsewhere and where the image has no data.
std::vector<std::uint8_t> explained_pixels(const RangeImage& scene, const PartDistanceField& part,
                                           const RigidTransform& T_scene_part, double distance_mm);

// 1 per pixel of `pixels` (a mask of the scene's size) over or under the part placed at
// T_scene_part: the line through its point along the scene's z axis (the belt's normal)
// passes within distance_mm of the part's surface, within reach_mm of the part's origin (the
// part's diameter covers it). That is the part's footprint on the belt, all of it, not only
// what the scan saw: what a recognized part leaves unexplained inside its footprint is its
// own unmodelled or mis-registered surface; what lies outside every footprint is another
// object. The line is traced through the distance field in steps of the distance itself.
std::vector<std::uint8_t> footprint_pixels(const RangeImage& scene,
                                           const std::vector<std::uint8_t>& pixels,
                                           const PartDistanceField& part,
                                           const RigidTransform& T_scene_part, double reach_mm,
                                           double distance_mm);

// Pixels of `mask` whose 8 neighbours are in it too: what is left of a region once its
// one-pixel fringe (mixed pixels at the explained part's border, noise) is taken away.
std::int64_t interior_pixels(const std::vector<std::uint8_t>& mask, int width, int height);

}  // namespace cosmos
