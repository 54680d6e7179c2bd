// The recognizer's searches beyond the views §5.2 selects (recognizer.hpp): the poses the vote
// index proposes, and the field-ranked pose search over a part's views or resting poses.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/indexing/pose_voting.hpp"
#include "core/recognition/free_space.hpp"
#include "core/recognition/part_pose_search.hpp"
#include "core/recognition/ranked_candidates.hpp"
#include "core/recognition/recognizer.hpp"
#include "core/recognition/resting_pose_search.hpp"
#include "core/recognition/signature_rank.hpp"
#include "core/stage_clock.hpp"

namespace cosmos {
namespace {

// The shares of the parts whose quick fits a task runner may fit at once: a few per core of a
// small machine, so that a share of slow parts does not leave the other cores idle at its end.
constexpr int kQuickFitShares = 8;

}  // namespace

std::vector<int> close_fitting_parts(std::span<const QuickFieldFit> quick_fits,
                                     double close_fit_mm2) {
  std::vector<int> parts;
  for (const QuickFieldFit& quick : quick_fits)
    if (quick.on_belt && quick.fit_mm2 <= close_fit_mm2) parts.push_back(quick.part);
  return parts;
}

std::optional<RecognitionCandidate> Recognizer::register_part_poses(
    const ViewAnalysis& scene, const ScenePoints& scene_points, ModelSurfaces& surfaces, int part,
    std::span<const RigidTransform> T_part_scene, RecognitionResult& result) const {
  const PartSearchModel& model = part_search_model(part);
  if (model.start_views.empty() || T_part_scene.empty()) return std::nullopt;
  // The poses as starts on one of the part's views; aligning them in the part's field moves
  // each onto the view nearest to it (part_pose_search.hpp).
  const int view = model.views[model.start_views.front()];
  const RigidTransform& T_view_part =
      model_base_.views[static_cast<std::size_t>(view)].T_scanner_part;
  std::vector<RigidTransform> starts;
  starts.reserve(T_part_scene.size());
  for (const RigidTransform& pose : T_part_scene) starts.push_back(T_view_part * pose);
  StageClock::time_point stage = StageClock::now();
  const std::vector<ViewPoseHypothesis> aligned = align_view_starts_in_field(
      scene_points.all, model_base_, view, starts, model, parameters_.field_starts,
      parameters_.search, parameters_.registered_hypotheses);
  result.timings.registration_ms += elapsed_ms(stage);
  if (aligned.empty()) return std::nullopt;
  RecognitionCandidate candidate;
  candidate.part = part;
  candidate.view = aligned.front().view;
  const ModelBaseView& nearest = model_base_.views[static_cast<std::size_t>(candidate.view)];
  candidate.spectral_distance = selector_.distance(scene.moments, nearest.moments);
  stage = StageClock::now();
  candidate.goodness = match_patch_groups(scene.view, nearest.cosmos, parameters_.matching).score;
  result.timings.matching_ms += elapsed_ms(stage);
  stage = StageClock::now();
  register_candidate(scene_points, aligned, surfaces, candidate);
  result.timings.registration_ms += elapsed_ms(stage);
  return candidate;
}

void Recognizer::verify_voted_poses(const ViewAnalysis& scene, const ScenePoints& scene_points,
                                    ModelSurfaces& surfaces, RecognitionResult& result) const {
  const StageClock::time_point stage = StageClock::now();
  PoseVoter voter(patch_pair_table_, parameters_.vote_index.voting);
  const std::span<const VotedPose> voted = voter.vote(scene.view);
  result.timings.selection_ms += elapsed_ms(stage);
  std::vector<RigidTransform> T_part_scene;
  for (std::size_t first = 0; first < voted.size(); ++first) {
    const int part = voted[first].part;
    if (std::any_of(voted.begin(), voted.begin() + static_cast<std::ptrdiff_t>(first),
                    [part](const VotedPose& earlier) { return earlier.part == part; }))
      continue;
    T_part_scene.clear();
    for (std::size_t v = first; v < voted.size(); ++v)
      if (voted[v].part == part) T_part_scene.push_back(voted[v].T_part_scene);
    std::optional<RecognitionCandidate> candidate =
        register_part_poses(scene, scene_points, surfaces, part, T_part_scene, result);
    if (!candidate) continue;
    candidate->from_vote_index = true;
    result.candidates.push_back(*candidate);
    ++result.views_examined;
  }
}

void Recognizer::register_scaled_size(const ViewAnalysis& scene, const ScenePoints& scene_points,
                                      ModelSurfaces& surfaces, int part, int posed_part,
                                      RecognitionResult& result) const {
  const ModelPart& posed = model_base_.parts[static_cast<std::size_t>(posed_part)];
  if (!(posed.diameter_mm > 0)) return;
  std::vector<RigidTransform> T_posed_scene;
  for (const RecognitionCandidate& candidate : result.candidates)
    if (candidate.part == posed_part && candidate.registered)
      T_posed_scene.push_back(
          model_base_.views[static_cast<std::size_t>(candidate.view)].T_scanner_part.inverse() *
          candidate.T_model_scene);
  const double scale =
      model_base_.parts[static_cast<std::size_t>(part)].diameter_mm / posed.diameter_mm;
  const Eigen::Vector3d centroid_mm = scene_points.all.position_mm.rowwise().mean();
  std::optional<RecognitionCandidate> candidate =
      register_part_poses(scene, scene_points, surfaces, part,
                          scaled_size_starts(T_posed_scene, scale, centroid_mm), result);
  if (!candidate) return;
  candidate->from_scaled_size = true;
  result.candidates.push_back(*candidate);
}

bool Recognizer::search_candidate_parts(const ViewAnalysis& scene, const ScenePoints& scene_points,
                                        ModelSurfaces& surfaces, RecognitionResult& result,
                                        const std::vector<int>& only_parts,
                                        bool resting_poses) const {
  // Parts in the order of their closest view, or of their quick field fit.
  std::vector<int> parts = only_parts;
  if (parts.empty()) {
    parts = selector_.rank_parts(scene.moments);
    if (parts.size() > static_cast<std::size_t>(parameters_.searched_parts))
      parts.resize(static_cast<std::size_t>(parameters_.searched_parts));
  }
  // Over every part, the parts that cannot be the scene's by size are left out
  // (part_size_gate.hpp): in a large catalog many of them, before any is fitted.
  if (only_parts.empty()) {
    result.parts_smaller_than_scene = result.parts_thicker_than_scene = 0;
    std::erase_if(parts, [&](int part) {
      return !admitted_by_size(part, scene_points.extent, scene_points.parts, result);
    });
  }
  const bool quick_ranked =
      only_parts.empty() && !resting_poses && parameters_.catalog_rank.enabled;
  std::vector<QuickFieldFit>& ranked = result.quick_fits;
  std::size_t left_out_by_signature = 0;
  if (quick_ranked) {
    const StageClock::time_point stage = StageClock::now();
    ranked.assign(parts.size(), QuickFieldFit{});
    // Each part's quick fit reads the scene and its own field alone: a few shares of the parts,
    // each fitting its own into its own slots.
    const auto quick_fit_parts = [&](std::size_t begin, std::size_t end) {
      const int shares = static_cast<int>(std::min(end - begin, std::size_t{kQuickFitShares}));
      tasks_.run(shares, [&](int share) {
        const auto share_of = [&](int s) {
          return begin +
                 (end - begin) * static_cast<std::size_t>(s) / static_cast<std::size_t>(shares);
        };
        for (std::size_t k = share_of(share); k < share_of(share + 1); ++k)
          ranked[k] = quick_fit(parts[k], scene_points);
      });
    };
    // The parts of closest signature first (signature_rank.hpp); the others only when none of
    // those fits closely, in tiers while they fit better, and otherwise never searched.
    std::size_t fitted_first = parts.size();
    if (!scene_points.signature.empty()) {
      const std::vector<PartSignatureDistance> by_signature =
          rank_by_signature(scene_points.signature, parts, model_base_, part_search_models_);
      for (std::size_t k = 0; k < parts.size(); ++k) parts[k] = by_signature[k].part;
      fitted_first = parts_fitted_first(by_signature, parameters_.signature_rank);
    }
    quick_fit_parts(0, fitted_first);
    const bool one_fits_closely =
        std::any_of(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(fitted_first),
                    [&](const QuickFieldFit& quick) {
                      return quick.on_belt && quick.fit_mm2 <= parameters_.signature_rank.fit_mm2;
                    });
    std::size_t fitted = fitted_first;
    if (!one_fits_closely) {
      const auto best_fit_mm2 = [&](std::size_t begin, std::size_t end) {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t k = begin; k < end; ++k) best = std::min(best, ranked[k].fit_mm2);
        return best;
      };
      double best_mm2 = best_fit_mm2(0, fitted);
      while (fitted < parts.size()) {
        const std::size_t end = std::min(
            parts.size(), fitted + static_cast<std::size_t>(parameters_.signature_rank.tier_parts));
        quick_fit_parts(fitted, end);
        const double tier_best_mm2 = best_fit_mm2(fitted, end);
        fitted = end;
        if (!(tier_best_mm2 < best_mm2)) break;
        best_mm2 = tier_best_mm2;
      }
    }
    left_out_by_signature = parts.size() - fitted;
    parts.resize(fitted);
    ranked.resize(fitted);
    result.parts_left_out_by_signature = static_cast<int>(left_out_by_signature);
    std::stable_sort(
        ranked.begin(), ranked.end(),
        [](const QuickFieldFit& a, const QuickFieldFit& b) { return a.fit_mm2 < b.fit_mm2; });
    for (std::size_t k = 0; k < ranked.size(); ++k) parts[k] = ranked[k].part;
    result.timings.selection_ms += elapsed_ms(stage);
  }
  // Registers one part's field poses; true when one explains enough to end the search.
  int parts_registered = 0;
  auto register_part = [&](int part, const std::vector<FieldHypothesis>& field_poses) {
    ++parts_registered;
    StageClock::time_point stage = StageClock::now();
    const bool fits_convincingly =
        !field_poses.empty() &&
        field_poses.front().truncated_mean_square_mm2 <= parameters_.convincing_field_fit_mm2;
    const std::vector<ViewPoseHypothesis> hypotheses = register_field_hypotheses(
        scene_points.all, model_base_, part_search_model(part), field_poses,
        parameters_.registration, parameters_.search, surfaces, tasks_);
    result.timings.registration_ms += elapsed_ms(stage);
    for (const ViewPoseHypothesis& hypothesis : hypotheses) {
      const ModelBaseView& view = model_base_.views[static_cast<std::size_t>(hypothesis.view)];
      RecognitionCandidate candidate;
      candidate.view = hypothesis.view;
      candidate.part = part;
      candidate.from_pose_search = !resting_poses;
      candidate.from_resting_search = resting_poses;
      candidate.spectral_distance = selector_.distance(scene.moments, view.moments);
      stage = StageClock::now();
      candidate.goodness = match_patch_groups(scene.view, view.cosmos, parameters_.matching).score;
      result.timings.matching_ms += elapsed_ms(stage);
      stage = StageClock::now();
      register_candidate(scene_points, {hypothesis}, surfaces, candidate);
      result.timings.registration_ms += elapsed_ms(stage);
      result.candidates.push_back(candidate);
      // As in verification: a pose that explains this much of the scene ends the search.
      if (explains_scene(candidate)) return true;
      if (&hypothesis == &hypotheses.front() && !fits_convincingly && candidate.registered &&
          candidate.inlier_fraction < parameters_.abandoned_part_support)
        return false;
    }
    return false;
  };
  // The field stages rank the parts far better than the spectra do: a part whose fit is
  // convincing is registered at once, the others wait and are registered in the order of
  // their fit, so a scene whose part ranks tenth by spectrum no longer registers nine wrong
  // parts first.
  struct WaitingPart {
    int part;
    std::vector<FieldHypothesis> field_poses;
    double best_fit_mm2;
  };
  std::vector<WaitingPart> waiting;
  double best_fit_mm2_of_all = std::numeric_limits<double>::infinity();
  bool every_part = true;
  // In quick order a part that explains the scene ends the search after the next part, its
  // rival (part_ambiguity.hpp): a view that two parts explain alike is no proof of either.
  bool explained = false;
  // The budget of registrations (registered_parts) holds for the search over views; the
  // rival of a part that explained the scene is searched whatever it.
  const auto budget_spent = [&] {
    return !resting_poses && parts_registered >= parameters_.registered_parts;
  };
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const int part = parts[k];
    if (budget_spent() && !explained) {
      every_part = false;
      break;
    }
    // A part whose quick fit is hopeless beside another part's full fit (the rule below) is
    // not searched, nor are those after it: the full stages rarely lower a fit that much.
    if (quick_ranked &&
        ranked[k].fit_mm2 > parameters_.search.worst_kept_score_mm2(best_fit_mm2_of_all)) {
      if (explained) return false;
      every_part = false;
      break;
    }
    if (!resting_poses)
      result.views_examined += static_cast<int>(part_search_model(part).views.size());
    StageClock::time_point stage = StageClock::now();
    std::vector<FieldHypothesis> field_poses =
        resting_poses
            ? resting_pose_hypotheses(scene_points.all, model_base_, part, part_search_model(part),
                                      parameters_.search, parameters_.resting)
            : field_pose_hypotheses(scene_points.all, model_base_, part_search_model(part),
                                    parameters_.search, tasks_, scene_points.views);
    if (!resting_poses) {
      drop_floating_poses(part, field_poses);
      drop_poses_over_belt(part, scene_points.image, field_poses);
    }
    result.timings.registration_ms += elapsed_ms(stage);
    const double best_fit_mm2 = field_poses.empty() ? std::numeric_limits<double>::infinity()
                                                    : field_poses.front().truncated_mean_square_mm2;
    best_fit_mm2_of_all = std::min(best_fit_mm2_of_all, best_fit_mm2);
    if (quick_ranked) result.best_field_fit_mm2 = best_fit_mm2_of_all;
    // The resting poses' field stages are cheap: every part's are run and the parts
    // registered in the order of their fit. In quick order the first part is the scene's
    // own nearly always, and is registered whatever its fit; so is the rival after it.
    const bool convincing = best_fit_mm2 <= parameters_.convincing_field_fit_mm2 ||
                            (quick_ranked && (k == 0 || explained));
    if (!resting_poses && convincing) {
      const bool explains = register_part(part, field_poses);
      if (explained || (explains && (!quick_ranked || k + 1 == parts.size())))
        return k + 1 == parts.size() && left_out_by_signature == 0;
      explained = explains;
    } else {
      waiting.push_back({part, std::move(field_poses), best_fit_mm2});
    }
  }
  std::stable_sort(waiting.begin(), waiting.end(), [](const WaitingPart& a, const WaitingPart& b) {
    return a.best_fit_mm2 < b.best_fit_mm2;
  });
  // As among one part's poses: a part that fits many times worse than the best one cannot
  // explain the scene as well, and is not registered; nor, past the resting poses' search,
  // are more than registered_waiting_parts of the others.
  const double hopeless_fit_mm2 = parameters_.search.worst_kept_score_mm2(best_fit_mm2_of_all);
  int registered = 0;
  for (const WaitingPart& part : waiting) {
    if (part.best_fit_mm2 > hopeless_fit_mm2) break;
    if (!resting_poses && registered >= parameters_.registered_waiting_parts) break;
    if (budget_spent()) break;
    ++registered;
    if (register_part(part.part, part.field_poses)) break;
  }
  return every_part && left_out_by_signature == 0;
}

bool Recognizer::admitted_by_size(int part, const SceneExtent& extent, SceneParts parts,
                                  RecognitionResult& result) const {
  const SizeVerdict verdict =
      judge_part_size(part_extents_[static_cast<std::size_t>(part)], extent, parts,
                      parameters_.resting.parts_touch_belt, parameters_.size_gate);
  result.parts_smaller_than_scene += verdict == SizeVerdict::kSmallerThanScene ? 1 : 0;
  result.parts_thicker_than_scene += verdict == SizeVerdict::kThickerThanScene ? 1 : 0;
  return verdict == SizeVerdict::kFits;
}

QuickFieldFit Recognizer::quick_fit(int part, const ScenePoints& scene_points) const {
  const std::vector<FieldHypothesis> quick =
      quick_field_poses(scene_points.quick, model_base_, part_search_model(part),
                        parameters_.search, parameters_.catalog_rank, scene_points.views);
  if (quick.empty()) return {part, std::numeric_limits<double>::infinity(), false};
  // Only the best pose that lies on the belt ranks the part: the poses are best first, and
  // those after it need no test.
  for (const FieldHypothesis& hypothesis : quick)
    if (!floats(part, hypothesis) && !stands_over_belt(part, scene_points.image, hypothesis))
      return {part, hypothesis.truncated_mean_square_mm2, true};
  return {part,
          parameters_.catalog_rank.floating_fit_factor * quick.front().truncated_mean_square_mm2,
          false};
}

bool Recognizer::floats(int part, const FieldHypothesis& hypothesis) const {
  const RestingSearchParameters& resting = parameters_.resting;
  if (!resting.parts_touch_belt && !resting.parts_rest) return false;
  const ModelPart& model_part = model_base_.parts[static_cast<std::size_t>(part)];
  return std::abs(
             cosmos::check_resting(model_part, hypothesis.T_part_scene, resting).lowest_point_mm) >
         resting.field_height_error_mm;
}

bool Recognizer::stands_over_belt(int part, const RangeImage& scene,
                                  const FieldHypothesis& hypothesis) const {
  if (parameters_.max_fraction_over_belt >= 1) return false;
  return fraction_over_belt(scene, part_search_model(part).surface_sample_mm,
                            hypothesis.T_part_scene) > parameters_.max_fraction_over_belt;
}

void Recognizer::drop_floating_poses(int part, std::vector<FieldHypothesis>& field_poses) const {
  std::erase_if(field_poses,
                [&](const FieldHypothesis& hypothesis) { return floats(part, hypothesis); });
}

void Recognizer::drop_poses_over_belt(int part, const RangeImage& scene,
                                      std::vector<FieldHypothesis>& field_poses) const {
  std::erase_if(field_poses, [&](const FieldHypothesis& hypothesis) {
    return stands_over_belt(part, scene, hypothesis);
  });
}

}  // namespace cosmos
