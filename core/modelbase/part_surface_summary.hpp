#pragma once
// What the recognizer's searches need of a part's whole surface, computed once from its views
// when the base is built and stored with it: per part the voxels its views' control points
// occupy (the pose search's distance field, part_distance_field.hpp, is their distance
// transform) and an even sample of those points (free_space.hpp), per view the centroid of its
// control points. Computing them needs every view of the part unpacked; a recognizer that did
// so for every part of a catalog of hundreds spent most of its start-up there.
#include "core/modelbase/model_base.hpp"
#include "core/registration/part_surface_voxels.hpp"

namespace cosmos {

// Points in ModelPart::surface_sample_mm, about: enough that a few pixels of a silhouette do
// not decide a fraction, few enough to check every quick pose of every part.
inline constexpr std::size_t kSurfaceSamplePoints = 256;

// Fills the part's surface_voxels and surface_sample_mm and its views'
// control_point_centroid_mm from the views' control points. Parts are independent: a builder
// may summarize them on several threads.
void summarize_part_surface(ModelBase& base, int part,
                            const PartDistanceFieldParameters& parameters);

// The same for every part.
void summarize_part_surfaces(ModelBase& base, const PartDistanceFieldParameters& parameters);

}  // namespace cosmos
