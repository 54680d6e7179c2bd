// The recognizer's path for a scene without a fitted surface (thin_scene.hpp): the parts in the
// order of their quick field fit on the range points, the first few searched in full, and the
// best pose of each that, set down on the belt, fits inside the scene's silhouette judged.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/recognition/free_space.hpp"
#include "core/recognition/part_pose_search.hpp"
#include "core/recognition/recognizer.hpp"
#include "core/recognition/resting_pose_search.hpp"
#include "core/recognition/thin_scene.hpp"
#include "core/stage_clock.hpp"

namespace cosmos {
namespace {

std::string percent(double fraction) { return std::to_string(std::lround(100 * fraction)); }

// One pose of a part, set down on the belt, and how it fits the range points and the scene's
// free space.
struct SettledPose {
  int part = -1;
  RigidTransform T_part_scene;
  double mean_square_mm2 = 0;
  double fraction_over_belt = 0;
  double inlier_fraction = 0;
};

}  // namespace

std::string Recognizer::recognize_thin_scene(const RangeImage& scene,
                                             RecognitionResult& result) const {
  const ThinSceneParameters& thin = parameters_.thin_scene;
  const StageClock::time_point start = StageClock::now();
  const RegistrationPoints points = range_points(scene, thin.max_points);
  // The field's zero set lies inside a rim, so a ribbon along the rim pulls the part up off
  // the belt, or slides it onto its face: each pose is set down on the belt, where the part
  // lies, before it is judged.
  const auto settle = [&](int part, const RigidTransform& T_part_scene) {
    const PartSearchModel& model = part_search_model(part);
    const ModelPart& model_part = model_base_.parts[static_cast<std::size_t>(part)];
    const auto set_down = [&](const RigidTransform& T) {
      const double lowest_mm =
          cosmos::check_resting(model_part, T, parameters_.resting).lowest_point_mm;
      return T * RigidTransform{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, lowest_mm)};
    };
    RigidTransform T = set_down(T_part_scene);
    for (int round = 0; round < thin.settle_rounds; ++round)
      T = set_down(align_in_distance_field(points, model.field, T, thin.settle_iterations,
                                           parameters_.search.field_truncation_mm));
    SettledPose settled{part, T};
    // The whole part inside the image: in the cell a piece its shadow cut off another part
    // is thin too, and beyond its blob's rows, where the rest of that part lies, any part
    // would stand unseen.
    settled.fraction_over_belt =
        fraction_over_belt(scene, model.surface_sample_mm, settled.T_part_scene,
                           thin.belt_margin_px, BeyondTheImage::kBelt);
    settled.mean_square_mm2 = field_truncated_mean_square_mm2(
        points, model.field, settled.T_part_scene, parameters_.search.field_truncation_mm);
    return settled;
  };
  // The best of a part's poses that stand inside the silhouette.
  const auto best_settled = [&](int part, const std::vector<FieldHypothesis>& poses,
                                double max_fraction_over_belt) {
    std::optional<SettledPose> best;
    for (const FieldHypothesis& pose : poses) {
      const SettledPose settled = settle(part, pose.T_part_scene);
      if (settled.fraction_over_belt > max_fraction_over_belt) continue;
      if (!best || settled.mean_square_mm2 < best->mean_square_mm2) best = settled;
    }
    return best;
  };

  std::vector<std::pair<double, int>> ranked;  // (quick fit, part), best first
  for (int part = 0; part < static_cast<int>(model_base_.parts.size()); ++part) {
    const std::optional<SettledPose> quick =
        best_settled(part,
                     quick_field_poses(points, model_base_, part_search_model(part),
                                       parameters_.search, parameters_.catalog_rank),
                     parameters_.max_fraction_over_belt);
    if (quick) ranked.emplace_back(quick->mean_square_mm2, part);
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  result.timings.selection_ms += elapsed_ms(start);

  const StageClock::time_point search_start = StageClock::now();
  PartPoseSearchParameters search = parameters_.search;
  search.refined_hypotheses = thin.hypotheses;
  std::vector<SettledPose> fits;
  const std::size_t searched =
      std::min(ranked.size(), static_cast<std::size_t>(thin.searched_parts));
  for (std::size_t k = 0; k < searched; ++k) {
    const int part = ranked[k].second;
    const PartSearchModel& model = part_search_model(part);
    std::optional<SettledPose> best =
        best_settled(part, field_pose_hypotheses(points, model_base_, model, search),
                     thin.max_fraction_over_belt);
    if (!best) continue;
    best->inlier_fraction =
        field_fraction_within(points, model.field, best->T_part_scene, thin.inlier_distance_mm);
    fits.push_back(*best);
  }
  std::stable_sort(fits.begin(), fits.end(), [](const SettledPose& a, const SettledPose& b) {
    return a.mean_square_mm2 < b.mean_square_mm2;
  });
  result.timings.registration_ms += elapsed_ms(search_start);
  result.thin_scene = true;
  if (fits.empty()) return "no part stands inside its thin silhouette";
  const SettledPose& best = fits.front();
  result.best_candidate_part = best.part;
  const auto name = [this](int part) {
    return model_base_.parts[static_cast<std::size_t>(part)].name;
  };
  if (best.inlier_fraction < thin.min_inlier_fraction)
    return "its best part, " + name(best.part) + ", lies near only " +
           percent(best.inlier_fraction) + " % of its range points";
  if (fits.size() > 1) {
    result.runner_up_part = fits[1].part;
    if (fits[1].mean_square_mm2 < thin.ambiguity_factor * best.mean_square_mm2)
      return "ambiguous between " + name(best.part) + " and " + name(fits[1].part);
  }
  result.part = best.part;
  result.view = nearest_view(model_base_, best.part, best.T_part_scene);
  result.T_scanner_part = best.T_part_scene.inverse().normalized();
  result.registration_rms_mm = std::sqrt(best.mean_square_mm2);
  result.inlier_fraction = best.inlier_fraction;
  result.score = best.inlier_fraction;
  result.seen_fraction = 1 - best.fraction_over_belt;
  result.status = RecognitionStatus::kOk;
  return {};
}

}  // namespace cosmos
