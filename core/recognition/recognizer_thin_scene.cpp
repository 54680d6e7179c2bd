// The recognizer's path for a scene without a fitted surface (thin_scene.hpp): the parts the
// scene's size allows (part_size_gate.hpp, on its range points) in the order of their quick
// field fit on those points, the first few searched in full, and the best pose of each that,
// set down on the belt, fits inside the scene's silhouette (ThinSceneFit) judged.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/recognition/part_pose_search.hpp"
#include "core/recognition/recognizer.hpp"
#include "core/recognition/thin_scene.hpp"
#include "core/stage_clock.hpp"

namespace cosmos {
namespace {

std::string percent(double fraction) { return std::to_string(std::lround(100 * fraction)); }

}  // namespace

const SettledPose* Recognizer::size_told_apart_on_ribbon(
    const std::vector<SettledPose>& fits) const {
  if (fits.empty() || !parameters_.size_variants.search) return nullptr;
  const int family_part = fits.front().part;
  const auto explaining_size = [&](const SettledPose& fit) {
    return (fit.part == family_part || is_size_variant(family_part, fit.part)) &&
           fit.inlier_fraction >= parameters_.thin_scene.min_inlier_fraction;
  };
  // The best fit by distance explaining too little is rejected so, whatever the other sizes.
  if (!explaining_size(fits.front())) return nullptr;
  const SettledPose* least_over_belt = &fits.front();
  for (const SettledPose& fit : fits)
    if (explaining_size(fit) && fit.fraction_over_belt < least_over_belt->fraction_over_belt)
      least_over_belt = &fit;
  const bool told_apart = std::all_of(fits.begin(), fits.end(), [&](const SettledPose& fit) {
    return !explaining_size(fit) || fit.part == least_over_belt->part ||
           (fit.fraction_over_belt - least_over_belt->fraction_over_belt >=
                parameters_.size_variants.fit_margin &&
            least_over_belt->inlier_fraction >= fit.inlier_fraction);
  });
  return told_apart ? least_over_belt : nullptr;
}

std::string Recognizer::recognize_thin_scene(const RangeImage& scene, SceneParts parts,
                                             RecognitionResult& result) const {
  const ThinSceneParameters& thin = parameters_.thin_scene;
  const StageClock::time_point start = StageClock::now();
  const RegistrationPoints points = range_points(scene, thin.max_points);
  const ThinSceneFit fit(scene, points, thin, parameters_.resting,
                         parameters_.search.field_truncation_mm);
  const auto part_of = [this](int part) -> const ModelPart& {
    return model_base_.parts[static_cast<std::size_t>(part)];
  };

  std::vector<std::pair<double, int>> ranked;  // (quick fit, part), best first
  const QuickFitPoints quick_points = quick_fit_points(points, parameters_.catalog_rank);
  // A ribbon's range points lie on its part as a surface's control points do: the same bounds
  // leave out the parts too small or too thick for it before any is fitted, which in a large
  // catalog is most of the cost of a thin scene.
  const SceneExtent extent = scene_extent(points, scene);
  result.parts_smaller_than_scene = result.parts_thicker_than_scene = 0;
  for (int part = 0; part < static_cast<int>(model_base_.parts.size()); ++part) {
    if (!admitted_by_size(part, extent, parts, result)) continue;
    const PartSearchModel& model = part_search_model(part);
    const std::optional<SettledPose> quick =
        fit.best_settled(part, part_of(part), model,
                         quick_field_poses(quick_points, model_base_, model, parameters_.search,
                                           parameters_.catalog_rank),
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
  const auto search_part = [&](int part) {
    const PartSearchModel& model = part_search_model(part);
    const std::optional<SettledPose> best = fit.best_settled(
        part, part_of(part), model, field_pose_hypotheses(points, model_base_, model, search),
        thin.max_fraction_over_belt);
    if (best) fits.push_back(*best);
  };
  const auto by_fit = [](const SettledPose& a, const SettledPose& b) {
    return a.mean_square_mm2 < b.mean_square_mm2;
  };
  const std::size_t searched =
      std::min(ranked.size(), static_cast<std::size_t>(thin.searched_parts));
  for (std::size_t k = 0; k < searched; ++k) search_part(ranked[k].second);
  std::stable_sort(fits.begin(), fits.end(), by_fit);
  // The winner's other sizes are searched too: a ribbon shows a rim, not the whole part, and a
  // larger size whose extra length lies in a shadow explains it as well.
  const auto searched_already = [&](int part) {
    return std::any_of(fits.begin(), fits.end(),
                       [part](const SettledPose& f) { return f.part == part; });
  };
  if (!fits.empty()) {
    const int winner = fits.front().part;
    for (int variant : size_variants_[static_cast<std::size_t>(winner)])
      if (!searched_already(variant)) search_part(variant);
    std::stable_sort(fits.begin(), fits.end(), by_fit);
  }
  result.timings.registration_ms += elapsed_ms(search_start);
  result.thin_scene = true;
  if (fits.empty()) return "no part stands inside its thin silhouette";
  const SettledPose* named_size = size_told_apart_on_ribbon(fits);
  const SettledPose& best = named_size ? *named_size : fits.front();
  result.best_candidate_part = best.part;
  const auto name = [&](int part) { return part_of(part).name; };
  if (best.inlier_fraction < thin.min_inlier_fraction)
    return "its best part, " + name(best.part) + ", lies near only " +
           percent(best.inlier_fraction) + " % of its range points";
  // Another part fitting nearly as well, or another size of it standing inside the silhouette
  // and explaining the ribbon at all, unless the fits told the sizes apart, leaves the scene
  // ambiguous: a wrong part is worse.
  for (const SettledPose& other : fits) {
    if (other.part == best.part) continue;
    if (result.runner_up_part < 0) result.runner_up_part = other.part;
    const bool other_size = is_size_variant(best.part, other.part);
    if (other_size && named_size) continue;
    if ((other_size && other.inlier_fraction >= thin.min_inlier_fraction) ||
        other.mean_square_mm2 < thin.ambiguity_factor * best.mean_square_mm2)
      return "ambiguous between " + name(best.part) + " and " + name(other.part);
  }
  result.part = best.part;
  result.view = nearest_view(model_base_, part_search_model(best.part), best.T_part_scene);
  result.T_scanner_part = best.T_part_scene.inverse().normalized();
  result.registration_rms_mm = std::sqrt(best.mean_square_mm2);
  result.inlier_fraction = best.inlier_fraction;
  result.score = best.inlier_fraction;
  result.seen_fraction = 1 - best.fraction_over_belt;
  result.status = RecognitionStatus::kOk;
  return {};
}

}  // namespace cosmos
