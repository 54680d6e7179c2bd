// The recognizer (recognizer.hpp): the scene's control points, the selected views verified
// around the searches (recognizer_searches.cpp), and each candidate registered and measured;
// the decision over the candidates is in recognizer_decision.cpp.
#include "core/recognition/recognizer.hpp"

#include <algorithm>
#include <cmath>

#include "core/indexing/pose_voting.hpp"
#include "core/modelbase/model_surface.hpp"
#include "core/recognition/part_pose_search.hpp"
#include "core/recognition/part_support.hpp"
#include "core/recognition/pose_hypotheses.hpp"
#include "core/recognition/surface_seen.hpp"
#include "core/stage_clock.hpp"

namespace cosmos {
namespace {

// Support and residual of a registered pose, from one correspondence pass with the inlier
// distance as the limit: the fraction of scene points the model surface explains, and the
// RMS distance over those.
struct Support {
  double inlier_fraction = 0;
  double rms_mm = 0;
};

Support measure_support(const RegistrationPoints& scene, const RegistrationPoints& model,
                        const RigidTransform& T_model_scene,
                        const RecognitionParameters& parameters, const TaskRunner& tasks) {
  RegistrationParameters strict = parameters.registration;
  strict.max_correspondence_distance_mm = parameters.support.inlier_distance_mm;
  const AlignmentScore score = score_alignment(scene, model, T_model_scene, strict, tasks);
  Support support;
  support.inlier_fraction = score.matched_fraction;
  // The truncated mean square counts unmatched points at the limit; take them out again.
  const double limit2 =
      parameters.support.inlier_distance_mm * parameters.support.inlier_distance_mm;
  const double unmatched = 1.0 - score.matched_fraction;
  if (score.matched_fraction > 0)
    support.rms_mm = std::sqrt(std::max(
        0.0, (score.truncated_mean_square_mm2 - unmatched * limit2) / score.matched_fraction));
  return support;
}

// The decision's figure of merit (§5.3.3 goodness and the ch. 6 residual together): support
// dominates, a residual near the limit and a poor COSMOS match lower it.
double candidate_score(double inlier_fraction, double rms_mm, double goodness,
                       const RecognitionParameters& parameters) {
  const double residual_factor = std::max(0.0, 1.0 - rms_mm / (2.0 * parameters.max_rms_mm));
  return inlier_fraction * residual_factor * (0.8 + 0.2 * std::clamp(goodness, 0.0, 1.0));
}

}  // namespace

const char* to_string(RecognitionStatus status) {
  return status == RecognitionStatus::kOk ? "ok" : "rejected";
}

Recognizer::Recognizer(const ModelBase& model_base, const CosmosParameters& cosmos,
                       const RecognitionParameters& parameters, const TaskRunner* tasks)
    : model_base_(model_base),
      tasks_(tasks != nullptr ? *tasks : one_after_another()),
      cosmos_(cosmos),
      parameters_(parameters),
      selector_(model_base, parameters.selection) {
  for (int part = 0; part < static_cast<int>(model_base.parts.size()); ++part) {
    part_search_models_.push_back(build_part_search_model(model_base, part));
    part_search_models_.back().belt = belt_contact_in_part_frame(part);
  }
  if (parameters_.vote_index.enabled)
    patch_pair_table_ = PatchPairTable(model_base, parameters_.vote_index.key);
  for (int part = 0; part < static_cast<int>(model_base.parts.size()); ++part)
    if (model_base.parts[static_cast<std::size_t>(part)].resting_coverage() <
        parameters_.resting.min_coverage)
      poorly_covered_parts_.push_back(part);
  size_variants_ = find_size_variants(model_base, parameters_.size_variants);
  for (const ModelPart& part : model_base.parts) part_extents_.push_back(part_extent(part));
}

RecognitionResult Recognizer::recognize(const RangeImage& scene, SceneParts parts) const {
  ViewAnalysisWorkspace workspace;
  return recognize(scene, workspace, parts);
}

RecognitionResult Recognizer::recognize(const RangeImage& scene, ViewAnalysisWorkspace& workspace,
                                        SceneParts parts) const {
  const StageClock::time_point start = StageClock::now();
  if (scene.width() == 0 || scene.count_valid() == 0) {
    RecognitionResult empty;
    empty.reason = "empty scan: no range data";
    empty.timings.total_ms = elapsed_ms(start);
    return empty;
  }
  const ViewAnalysis analysis = analyze_view(scene, cosmos_, workspace);
  return recognize_analyzed(scene, analysis, elapsed_ms(start), parts);
}

RecognitionResult Recognizer::recognize_analyzed(const RangeImage& scene,
                                                 const ViewAnalysis& analysis, double features_ms,
                                                 SceneParts parts) const {
  const StageClock::time_point start = StageClock::now();
  RecognitionResult result;
  result.moments = analysis.moments;
  result.scene_patches = static_cast<int>(analysis.view.patches.size());
  result.timings.features_ms = features_ms;
  const auto finish = [&](std::string reason) {
    result.reason = std::move(reason);
    result.timings.total_ms = features_ms + elapsed_ms(start);
    return result;
  };
  // A scene with too little fitted surface may be a thin part seen edge-on (thin_scene.hpp),
  // told from other parts only by where the scanner saw the belt.
  const auto finish_thin = [&](std::string reason) {
    const ThinSceneParameters& thin = parameters_.thin_scene;
    if (!thin.enabled || model_base_.views.empty() || !scene.belt_known() ||
        scene.count_valid() < static_cast<std::size_t>(thin.min_points))
      return finish(std::move(reason));
    const std::string thin_reason = recognize_thin_scene(scene, parts, result);
    return finish(thin_reason.empty() ? thin_reason
                                      : reason + "; searched as a thin scene, " + thin_reason);
  };
  if (analysis.valid_pixels == 0) return finish_thin("no object: no surface could be fitted");

  StageClock::time_point stage = StageClock::now();
  RegistrationPointsResult scene_points =
      build_registration_points(scene, parameters_.scene_points, &analysis.frames);
  // A small visible surface gets denser control points: a hundred points do not tell a
  // good pose from a poor one reliably.
  for (RegistrationPointParameters denser = parameters_.scene_points;
       scene_points.points.size() < parameters_.min_dense_scene_points && denser.stride_px > 1;) {
    denser.stride_px /= 2;
    scene_points = build_registration_points(scene, denser, &analysis.frames);
  }
  if (const int all = scene_points.points.size(); all > parameters_.max_scene_points) {
    std::vector<int> kept(static_cast<std::size_t>(parameters_.max_scene_points));
    for (std::size_t k = 0; k < kept.size(); ++k)
      kept[k] = static_cast<int>(k * static_cast<std::size_t>(all) / kept.size());
    scene_points.points = select_points(scene_points.points, kept);
  }
  result.scene_points = scene_points.points.size();
  result.timings.features_ms += elapsed_ms(stage);
  if (scene_points.status != RegistrationPointsStatus::kOk ||
      result.scene_points < parameters_.min_scene_points)
    return finish_thin("too little smooth surface to register (" +
                       std::to_string(result.scene_points) + " control points)");
  if (model_base_.views.empty()) return finish("the model base has no views");

  stage = StageClock::now();
  const std::vector<SpectralCandidate> selected = selector_.select(analysis.moments);
  result.timings.selection_ms = elapsed_ms(stage);

  ScenePoints points{std::move(scene_points.points), {}, {}, scene, parts, {}, {}, {}};
  points.coarse = spread_subset(points.all, parameters_.coarse_points);
  points.quick = quick_fit_points(points.all, parameters_.catalog_rank);
  points.extent = scene_extent(points.all, scene);
  points.views = view_size_gate(points.extent, parts, parameters_.resting.parts_touch_belt,
                                parameters_.size_gate);
  if (parameters_.signature_rank.enabled && parts == SceneParts::kOne &&
      parameters_.resting.parts_touch_belt)
    points.signature = view_signature(points.all.position_mm, 0.0);
  ModelSurfaces surfaces(model_base_, parameters_.surfaces);
  // The first views_before_search selected views are verified in nearly every scene (all but
  // a view of the part the first one found, passed over as its rival). With threads to spare
  // they are verified at once, each with its own surfaces, and taken in order below as though
  // verified there.
  const std::size_t first_views =
      tasks_.threads() > 1
          ? std::min(selected.size(), static_cast<std::size_t>(parameters_.views_before_search))
          : 0;
  std::vector<RecognitionCandidate> first_verified(first_views);
  std::vector<RecognitionTimings> first_timings(first_views);
  tasks_.run(static_cast<int>(first_views), [&](int k) {
    const auto view = static_cast<std::size_t>(k);
    const auto verify_with = [&](ModelSurfaces& view_surfaces) {
      first_verified[view] =
          verify(analysis, points, selected[view], view_surfaces, first_timings[view].matching_ms,
                 first_timings[view].registration_ms);
    };
    if (k == 0) return verify_with(surfaces);
    ModelSurfaces own(model_base_, parameters_.surfaces);
    verify_with(own);
  });
  const auto verified = [&](std::size_t view) {
    if (view >= first_views)
      return verify(analysis, points, selected[view], surfaces, result.timings.matching_ms,
                    result.timings.registration_ms);
    result.timings.matching_ms += first_timings[view].matching_ms;
    result.timings.registration_ms += first_timings[view].registration_ms;
    return std::move(first_verified[view]);
  };
  // Verifies the selected views from `next` up to `end` until one explains the scene. The
  // decision needs the best other part to compare with (part_ambiguity.hpp): once a view or a
  // search has explained the scene, the next selected views of parts not verified yet are
  // verified as its rivals, whichever order the views and the searches ran in.
  std::size_t next = 0;
  bool rivals_verified = false;
  const auto verify_rivals = [&] {
    rivals_verified = true;
    for (int rivals = 0;
         next < selected.size() && rivals < parameters_.ambiguity.rival_verifications; ++next) {
      const int part = model_base_.views[static_cast<std::size_t>(selected[next].view)].part_index;
      if (std::any_of(result.candidates.begin(), result.candidates.end(),
                      [part](const RecognitionCandidate& c) { return c.part == part; }))
        continue;
      result.candidates.push_back(verified(next));
      ++result.views_examined;
      ++rivals;
    }
  };
  const auto verify_selected = [&](std::size_t end) {
    while (next < end) {
      result.candidates.push_back(verified(next++));
      ++result.views_examined;
      if (explains_scene(result.candidates.back())) return verify_rivals();
    }
  };
  verify_selected(
      std::min(selected.size(), static_cast<std::size_t>(parameters_.views_before_search)));
  const auto explained = [&] {
    return std::any_of(result.candidates.begin(), result.candidates.end(),
                       [&](const RecognitionCandidate& c) { return explains_scene(c); });
  };
  // Only parts known to rest are searched in their resting poses: a tumbled part lies in none,
  // and the search only delays the others.
  if (parameters_.resting.search && parameters_.resting.parts_rest && !explained()) {
    result.resting_searched = true;
    search_candidate_parts(analysis, points, surfaces, result, {}, true);
  }
  // Parts known to rest have had every resting pose searched: the searches over views can only
  // add poses the decision refuses, except for the parts whose resting poses are not known
  // well enough to refuse a lean.
  const bool rest_searched = parameters_.resting.parts_rest && result.resting_searched;
  if (!explained() && parameters_.vote_index.enabled && !rest_searched)
    verify_voted_poses(analysis, points, surfaces, result);
  const std::vector<int> uncovered = rest_searched ? poorly_covered_parts_ : std::vector<int>{};
  if (!explained() && (!rest_searched || !uncovered.empty())) {
    result.catalog_searched =
        search_candidate_parts(analysis, points, surfaces, result, uncovered) && !rest_searched;
  }
  if (!explained())
    verify_selected(selected.size());
  else if (!rivals_verified)
    verify_rivals();
  return finish(decide(analysis, points, surfaces, result));
}

bool Recognizer::refine_free_motion(const ScenePoints& scene_points, ModelSurfaces& surfaces,
                                    RecognitionCandidate& candidate) const {
  if (!parameters_.free_motion.enabled) return false;
  const RegistrationPoints& model = surfaces.points(candidate.view);
  RegistrationParameters fine = parameters_.registration;
  fine.max_iterations = parameters_.fine_registration_iterations;
  // One more pass from the registered pose tells which motion its inliers leave free.
  const RegistrationResult registered = register_views(
      scene_points.all, model, candidate.T_model_scene, fine, tasks_, belt_contact(candidate.view));
  const std::optional<RigidTransform> start =
      search_free_motion(scene_points.coarse, model, registered, parameters_.registration,
                         parameters_.support.inlier_distance_mm, parameters_.free_motion, tasks_);
  if (!start) return false;
  const RegistrationResult again =
      register_views(scene_points.all, model, *start, fine, tasks_, belt_contact(candidate.view));
  if (again.status == RegistrationStatus::kInvalidInput) return false;
  const PartSupport support = measure_part_support(
      scene_points.all, model_base_, part_search_model(candidate.part).views, candidate.view,
      again.T_model_scene, parameters_.registration, parameters_.support, surfaces, tasks_);
  if (!(support.inlier_fraction > candidate.inlier_fraction)) return false;
  candidate.T_model_scene = again.T_model_scene;
  candidate.rms_mm = support.rms_mm;
  candidate.inlier_fraction = support.inlier_fraction;
  candidate.score =
      candidate_score(support.inlier_fraction, support.rms_mm, candidate.goodness, parameters_);
  return true;
}

RecognitionCandidate Recognizer::verify(const ViewAnalysis& scene, const ScenePoints& scene_points,
                                        const SpectralCandidate& selected, ModelSurfaces& surfaces,
                                        double& matching_ms, double& registration_ms) const {
  const ModelBaseView& view = model_base_.views[static_cast<std::size_t>(selected.view)];
  RecognitionCandidate candidate;
  candidate.view = selected.view;
  candidate.part = view.part_index;
  candidate.spectral_distance = selected.distance;

  StageClock::time_point stage = StageClock::now();
  const PatchGroupMatch match = match_patch_groups(scene.view, view.cosmos, parameters_.matching);
  candidate.goodness = match.score;
  const PoseFromPatches from_patches =
      estimate_pose_from_patches(scene.view, view.cosmos, match.pairs, parameters_.pose);
  matching_ms += elapsed_ms(stage);

  stage = StageClock::now();
  const std::vector<ViewPoseHypothesis> starts = align_view_starts_in_field(
      scene_points.all, model_base_, selected.view,
      generate_pose_hypotheses(scene_points.coarse, surfaces.points(selected.view), from_patches,
                               {.in_plane_turns = parameters_.in_plane_hypotheses}),
      part_search_model(view.part_index), parameters_.field_starts, parameters_.search,
      parameters_.registered_hypotheses);
  register_candidate(scene_points, starts, surfaces, candidate);
  registration_ms += elapsed_ms(stage);
  return candidate;
}

bool Recognizer::explains_scene(const RecognitionCandidate& candidate) const {
  // A part with other sizes in the base has all of them searched once it wins
  // (size_variants.hpp); searching on would only find a near size's marginally better pose.
  const double min_seen = size_variants_[static_cast<std::size_t>(candidate.part)].empty()
                              ? parameters_.sufficient_seen_fraction
                              : parameters_.min_seen_fraction;
  return candidate.registered && candidate.inlier_fraction >= parameters_.sufficient_support &&
         candidate.seen_fraction >= min_seen && at_rest(candidate);
}

bool Recognizer::at_rest(const RecognitionCandidate& candidate) const {
  const RestingSearchParameters& resting = parameters_.resting;
  if (!resting.parts_rest && !resting.parts_touch_belt) return true;
  const RestingCheck check = check_resting(candidate);
  return resting.parts_rest ? check.at_rest : check.touches_belt;
}

BeltContact Recognizer::belt_contact_in_part_frame(int part) const {
  const RestingSearchParameters& resting = parameters_.resting;
  if (!resting.parts_rest && !resting.parts_touch_belt) return {};
  return {model_base_.parts[static_cast<std::size_t>(part)].hull_vertices_mm,
          RigidTransform::identity(), resting.belt_contact_weight};
}

BeltContact Recognizer::belt_contact(int view) const {
  const ModelBaseView& model_view = model_base_.views[static_cast<std::size_t>(view)];
  BeltContact belt = belt_contact_in_part_frame(model_view.part_index);
  belt.T_model_part = model_view.T_scanner_part;
  return belt;
}

RestingCheck Recognizer::check_resting(const RecognitionCandidate& candidate) const {
  const ModelBaseView& view = model_base_.views[static_cast<std::size_t>(candidate.view)];
  return cosmos::check_resting(model_base_.parts[static_cast<std::size_t>(candidate.part)],
                               view.T_scanner_part.inverse() * candidate.T_model_scene,
                               parameters_.resting);
}

void Recognizer::register_candidate(const ScenePoints& scene_points,
                                    const std::vector<ViewPoseHypothesis>& starts,
                                    ModelSurfaces& surfaces,
                                    RecognitionCandidate& candidate) const {
  RegistrationResult best;
  int best_view = -1;
  bool best_refined = false;
  Support best_support;
  // Coarse to fine: the iterations far from the optimum on a spread subset, the last few on
  // every control point (ch. 6's estimate is the fine one).
  RegistrationParameters coarse = parameters_.registration;
  coarse.max_iterations = parameters_.coarse_registration_iterations;
  coarse.min_rejection_distance_mm = parameters_.coarse_min_rejection_distance_mm;
  RegistrationParameters fine = parameters_.registration;
  fine.max_iterations = parameters_.fine_registration_iterations;
  for (const ViewPoseHypothesis& start : starts) {
    const ModelBaseView& start_view = model_base_.views[static_cast<std::size_t>(start.view)];
    if (!parameters_.registration_gate.passes(
            scene_points.coarse, part_search_model(candidate.part).field,
            start_view.T_scanner_part.inverse() * start.T_model_scene))
      continue;
    const RegistrationPoints& model = surfaces.points(start.view);
    const BeltContact belt = belt_contact(start.view);
    RegistrationResult registration =
        register_views(scene_points.coarse, model, start.T_model_scene, coarse, tasks_, belt);
    if (registration.status == RegistrationStatus::kInvalidInput) continue;
    Support support = measure_support(scene_points.coarse, model, registration.T_model_scene,
                                      parameters_, tasks_);
    const bool refine = support.inlier_fraction >= parameters_.fine_registration_support;
    if (refine) {
      registration =
          register_views(scene_points.all, model, registration.T_model_scene, fine, tasks_, belt);
      // A degenerate (still planar) result is kept: its support decides.
      if (registration.status == RegistrationStatus::kInvalidInput) continue;
      support =
          measure_support(scene_points.all, model, registration.T_model_scene, parameters_, tasks_);
    }
    if (candidate.registered && support.inlier_fraction <= best_support.inlier_fraction) continue;
    candidate.registered = true;
    best = registration;
    best_support = support;
    best_view = start.view;
    best_refined = refine;
  }
  if (!candidate.registered) return;
  candidate.view = best_view;
  candidate.refined = best_refined;
  // Most candidates of the pose search are wrong parts: the spread subset tells them apart at
  // a fraction of the cost, and only the plausible ones are measured on every point.
  PartSupport support = measure_part_support(
      scene_points.coarse, model_base_, part_search_model(candidate.part).views, candidate.view,
      best.T_model_scene, parameters_.registration, parameters_.support, surfaces, tasks_);
  if (support.inlier_fraction >= parameters_.plausible_support)
    support = measure_part_support(
        scene_points.all, model_base_, part_search_model(candidate.part).views, candidate.view,
        best.T_model_scene, parameters_.registration, parameters_.support, surfaces, tasks_);
  candidate.registration_status = best.status;
  candidate.T_model_scene = best.T_model_scene;
  candidate.rms_mm = support.rms_mm;
  candidate.inlier_fraction = support.inlier_fraction;
  candidate.score =
      candidate_score(support.inlier_fraction, support.rms_mm, candidate.goodness, parameters_);
  candidate.seen_fraction =
      measure_surface_seen(scene_points.image, surfaces.points(candidate.view),
                           candidate.T_model_scene, parameters_.surface_seen)
          .seen_fraction();
}

}  // namespace cosmos
