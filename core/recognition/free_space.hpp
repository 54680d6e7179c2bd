#pragma once
// The free-space constraint on a pose hypothesis: a placed part must not stand where the
// scanner measured the bare belt. Seen from above, every point of a part projects inside the
// part's own silhouette, which the scan covers with surface or, in a camera or laser shadow,
// with nothing; it never covers it with belt the laser reached. A wrong part fitted to a few
// of the scene's faces (a flat face that dozens of prismatic parts contain) reaches out over
// that belt, and its field fit, which asks only whether the scene's points lie on the part,
// cannot tell it from the scene's own part. A sample of the part's surface is placed by the
// hypothesis and looked up in the scene's image: a point whose pixel and its eight
// neighbours (those in the image) all saw the belt lies over it, so that silhouettes a pixel
// off do not count (a wider margin for poses that are rougher still). Beyond the image, what its
// nearest border pixel saw: a scan's image ends on belt around the part; a part's view in the cell
// holds only its own blob's rows, and where its shadow cut the part in two, the border towards the
// other blob is shadow, not belt.
#include <Eigen/Core>

#include "core/range_image.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

// What a point beyond the image lies over: what the nearest border pixel saw, or the belt, for a
// search that must hold the whole part inside the image (thin_scene.hpp).
enum class BeyondTheImage { kBorderPixel, kBelt };

// The fraction of `points_part_mm` (part frame) that T_part_scene^-1 places over measured belt
// in `scene`, a point counting when every pixel within `margin_px` of its own saw the belt; 0
// when the image does not say where the belt was seen (RangeImage::belt_known).
double fraction_over_belt(const RangeImage& scene, const Eigen::Matrix3Xd& points_part_mm,
                          const RigidTransform& T_part_scene, int margin_px = 1,
                          BeyondTheImage beyond = BeyondTheImage::kBorderPixel);

}  // namespace cosmos
