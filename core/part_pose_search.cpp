#include "core/part_pose_search.hpp"

#include <algorithm>

#include "core/model_surface.hpp"
#include "core/pose_hypotheses.hpp"

namespace cosmos {

std::vector<ViewPoseHypothesis> search_part_pose(const RegistrationPoints& scene,
                                                 const ModelBase& base, int part,
                                                 const RegistrationParameters& registration,
                                                 const PartPoseSearchParameters& parameters) {
  std::vector<ViewPoseHypothesis> best;
  const RegistrationPoints scoring = spread_subset(scene, parameters.scoring_points);
  if (scoring.size() == 0) return best;
  const PoseFromPatches no_patch_pose;  // status too_few_pairs: not used
  const auto keep_best = [&best](std::size_t count) {
    // Ties by view, then generation order (stable).
    std::stable_sort(best.begin(), best.end(),
                     [](const ViewPoseHypothesis& a, const ViewPoseHypothesis& b) {
                       return a.truncated_mean_square_mm2 < b.truncated_mean_square_mm2;
                     });
    if (best.size() > count) best.resize(count);
  };
  const auto refined_count =
      static_cast<std::size_t>(std::max(parameters.refined_hypotheses, parameters.best_hypotheses));
  // Coarse pass over the once-subdivided sphere's views when the part has them (its view
  // spacing, ~23 degrees, is within what the refinement below converges from); a base
  // without them is searched over every view.
  RegistrationParameters coarse_registration = registration;
  coarse_registration.max_iterations = parameters.coarse_iterations;
  coarse_registration.max_correspondence_distance_mm = parameters.coarse_correspondence_distance_mm;
  bool has_coarse_views = false;
  for (const ModelBaseView& view : base.views)
    has_coarse_views |= view.part_index == part && is_once_subdivided_view(view.view_index);
  for (std::size_t v = 0; v < base.views.size(); ++v) {
    const ModelBaseView& view = base.views[v];
    if (view.part_index != part) continue;
    if (has_coarse_views && !is_once_subdivided_view(view.view_index)) continue;
    const ModelSurface model(view);
    for (const PoseHypothesis& hypothesis :
         pose_hypotheses(scoring, model.points(), no_patch_pose, registration,
                         {.in_plane_turns = parameters.in_plane_turns})) {
      RigidTransform T_model_scene = hypothesis.T_model_scene;
      const RegistrationResult settled =
          register_views(scoring, model.points(), T_model_scene, coarse_registration);
      if (settled.status != RegistrationStatus::invalid_input)
        T_model_scene = settled.T_model_scene;
      best.push_back({static_cast<int>(v), T_model_scene,
                      score_alignment(scoring, model.points(), T_model_scene, registration)
                          .truncated_mean_square_mm2});
    }
    keep_best(refined_count);
  }
  RegistrationParameters short_registration = registration;
  short_registration.max_iterations = parameters.refinement_iterations;
  const auto refine = [&](ViewPoseHypothesis& hypothesis, int view,
                          const RigidTransform& T_model_scene) {
    const ModelSurface model(base.views[static_cast<std::size_t>(view)]);
    const RegistrationResult refined =
        register_views(scoring, model.points(), T_model_scene, short_registration);
    if (refined.status == RegistrationStatus::invalid_input) return;
    const AlignmentScore score =
        score_alignment(scoring, model.points(), refined.T_model_scene, registration);
    if (score.truncated_mean_square_mm2 < hypothesis.truncated_mean_square_mm2) {
      hypothesis.view = view;
      hypothesis.T_model_scene = refined.T_model_scene;
      hypothesis.truncated_mean_square_mm2 = score.truncated_mean_square_mm2;
    }
  };
  for (ViewPoseHypothesis& hypothesis : best) {
    refine(hypothesis, hypothesis.view, hypothesis.T_model_scene);
    // Then onto the part's view nearest to the viewing direction that pose implies.
    const ModelBaseView& from = base.views[static_cast<std::size_t>(hypothesis.view)];
    const RigidTransform T_part_scene = from.T_scanner_part.inverse() * hypothesis.T_model_scene;
    const Eigen::Vector3d seen_from_part = T_part_scene.rotation * Eigen::Vector3d::UnitZ();
    int nearest = hypothesis.view;
    for (std::size_t v = 0; v < base.views.size(); ++v) {
      const ModelBaseView& view = base.views[v];
      if (view.part_index == part &&
          view.direction_part.dot(seen_from_part) >
              base.views[static_cast<std::size_t>(nearest)].direction_part.dot(seen_from_part))
        nearest = static_cast<int>(v);
    }
    if (nearest != hypothesis.view)
      refine(hypothesis, nearest,
             base.views[static_cast<std::size_t>(nearest)].T_scanner_part * T_part_scene);
  }
  keep_best(static_cast<std::size_t>(parameters.best_hypotheses));
  return best;
}

}  // namespace cosmos
