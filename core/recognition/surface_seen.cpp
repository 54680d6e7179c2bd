#include "core/recognition/surface_seen.hpp"

#include <cmath>

namespace cosmos {

SurfaceSeen measure_surface_seen(const RangeImage& scene, const RegistrationPoints& model,
                                 const RigidTransform& T_model_scene,
                                 const SurfaceSeenParameters& parameters) {
  SurfaceSeen result;
  if (scene.width() == 0 || scene.height() == 0) return result;
  const RigidTransform T_scene_model = T_model_scene.inverse();
  const double tolerance_mm = parameters.depth_tolerance_mm;
  const bool belt_known = scene.belt_known();
  const bool facing_known = parameters.sight && model.normal.cols() == model.position_mm.cols();
  for (Eigen::Index i = 0; i < model.position_mm.cols(); ++i) {
    const Eigen::Vector3d point = T_scene_model.apply(model.position_mm.col(i));
    const long column = scene.column_at(point.x());
    const long row = scene.row_at(point.y());
    if (facing_known &&
        !parameters.sight->measurable(point, T_scene_model.rotate(model.normal.col(i)))) {
      ++result.hidden;
      continue;
    }
    // Against the part: a lower surface, or the belt measured (beyond the image: its
    // background, belt as far as it can tell).
    bool seen = false, hidden = false, against = false;
    for (long r = row - 1; r <= row + 1 && !seen; ++r) {
      for (long c = column - 1; c <= column + 1 && !seen; ++c) {
        if (c < 0 || r < 0 || c >= scene.width() || r >= scene.height()) {
          against = true;
          continue;
        }
        const float z = scene.z_mm(static_cast<int>(c), static_cast<int>(r));
        if (std::isnan(z)) {
          against |= !belt_known || scene.belt_seen(static_cast<int>(c), static_cast<int>(r)) != 0;
          continue;
        }
        seen = std::abs(z - point.z()) <= tolerance_mm;
        hidden |= z > point.z() + tolerance_mm;
        against |= z < point.z() - tolerance_mm;
      }
    }
    if (seen)
      ++result.seen;
    else if (hidden || !against)
      ++result.hidden;
    else
      ++result.contradicted;
  }
  return result;
}

}  // namespace cosmos
