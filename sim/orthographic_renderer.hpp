#pragma once
// The ideal range image of a scene: an orthographic z-buffer, one Embree ray straight down at
// every pixel centre, the height of the first part surface it meets. No laser shadow, no
// camera occlusion, no dropouts, no noise, no belt (NaN where a ray meets no part): the
// reference that simulated scans, with their sensor-made missing data, are compared with.
#include "core/range_image.hpp"
#include "sim/conveyor_scene.hpp"

namespace cosmos {

// Fills image.z_mm on the image's own grid (size, pixel size and origin set by the caller,
// in the belt frame). The scene must be committed.
void render_orthographic(const ConveyorScene& scene, RangeImage& image);

}  // namespace cosmos
