#include "core/recognition/thin_scene.hpp"

#include <algorithm>
#include <cmath>

#include "core/recognition/free_space.hpp"

namespace cosmos {

RegistrationPoints range_points(const RangeImage& scene, int max_points) {
  const std::size_t count = scene.count_valid();
  const std::size_t step =
      std::max<std::size_t>(1, (count + static_cast<std::size_t>(max_points) - 1) /
                                   static_cast<std::size_t>(std::max(max_points, 1)));
  const auto kept = static_cast<Eigen::Index>((count + step - 1) / step);
  RegistrationPoints points;
  points.position_mm.resize(3, kept);
  points.normal.resize(3, kept);
  points.surface = decltype(points.surface)::Zero(kSurfaceCoefficients, kept);
  points.residual_rms_mm = Eigen::VectorXd::Zero(kept);
  std::size_t seen = 0;
  Eigen::Index k = 0;
  for (int row = 0; row < scene.height(); ++row)
    for (int column = 0; column < scene.width(); ++column) {
      if (!scene.has_data(column, row)) continue;
      if (seen++ % step != 0) continue;
      points.position_mm.col(k) = scene.point_mm(column, row);
      points.normal.col(k) = Eigen::Vector3d::UnitZ();
      ++k;
    }
  return points;
}

ThinSceneFit::ThinSceneFit(const RangeImage& scene, const RegistrationPoints& points,
                           const ThinSceneParameters& parameters,
                           const RestingSearchParameters& resting, double field_truncation_mm)
    : scene_(scene),
      points_(points),
      parameters_(parameters),
      resting_(resting),
      field_truncation_mm_(field_truncation_mm) {}

SettledPose ThinSceneFit::settle(int part, const ModelPart& model_part,
                                 const PartSearchModel& model,
                                 const RigidTransform& T_part_scene) const {
  const auto set_down = [&](const RigidTransform& T) {
    const double lowest_mm = check_resting(model_part, T, resting_).lowest_point_mm;
    if (!std::isfinite(lowest_mm)) return T;  // a part without hull corners
    return T * RigidTransform{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, lowest_mm)};
  };
  RigidTransform T = set_down(T_part_scene);
  for (int round = 0; round < parameters_.settle_rounds; ++round)
    T = set_down(align_in_distance_field(points_, model.field, T, parameters_.settle_iterations,
                                         field_truncation_mm_));
  SettledPose settled{part, T};
  settled.fraction_over_belt =
      fraction_over_belt(scene_, model.surface_sample_mm, settled.T_part_scene,
                         parameters_.belt_margin_px, BeyondTheImage::kBelt);
  settled.mean_square_mm2 = field_truncated_mean_square_mm2(
      points_, model.field, settled.T_part_scene, field_truncation_mm_);
  return settled;
}

std::optional<SettledPose> ThinSceneFit::best_settled(int part, const ModelPart& model_part,
                                                      const PartSearchModel& model,
                                                      const std::vector<FieldHypothesis>& poses,
                                                      double max_fraction_over_belt) const {
  std::optional<SettledPose> best;
  for (const FieldHypothesis& pose : poses) {
    const SettledPose settled = settle(part, model_part, model, pose.T_part_scene);
    if (settled.fraction_over_belt > max_fraction_over_belt) continue;
    if (!best || settled.mean_square_mm2 < best->mean_square_mm2) best = settled;
  }
  if (best)
    best->inlier_fraction = field_fraction_within(points_, model.field, best->T_part_scene,
                                                  parameters_.inlier_distance_mm);
  return best;
}

}  // namespace cosmos
