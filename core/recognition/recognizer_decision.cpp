// The recognizer's decision (recognizer.hpp): among the registered candidates, the winner and
// its rival, the rival's and the winner's other sizes searched before they are compared, and
// the rejections — not at rest, surface not seen, too little explained, ambiguous between two
// parts — each with its reason; then the winner's pose along the motion left free.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/recognition/part_ambiguity.hpp"
#include "core/recognition/ranked_candidates.hpp"
#include "core/recognition/recognizer.hpp"

namespace cosmos {

bool Recognizer::is_size_variant(int part, int other) const {
  const std::vector<int>& family = size_variants_[static_cast<std::size_t>(part)];
  return std::binary_search(family.begin(), family.end(), other);
}

std::vector<int> Recognizer::confusable_parts_unsearched(
    int part, const ScenePoints& points, const RecognitionResult& result,
    const std::function<bool(int)>& searched) const {
  const std::vector<int>& listed =
      model_base_.parts[static_cast<std::size_t>(part)].confusable_parts;
  if (listed.empty()) return {};
  struct Listed {
    int part;
    double quick_fit_mm2;
  };
  std::vector<Listed> kept;
  for (int other : listed) {
    if (searched(other) ||
        judge_part_size(part_extents_[static_cast<std::size_t>(other)], points.extent, points.parts,
                        parameters_.resting.parts_touch_belt,
                        parameters_.size_gate) != SizeVerdict::kFits)
      continue;
    const auto quick =
        std::find_if(result.quick_fits.begin(), result.quick_fits.end(),
                     [other](const QuickFieldFit& fit) { return fit.part == other; });
    kept.push_back({other, quick != result.quick_fits.end()
                               ? quick->fit_mm2
                               : std::numeric_limits<double>::infinity()});
  }
  std::stable_sort(kept.begin(), kept.end(), [](const Listed& a, const Listed& b) {
    return a.quick_fit_mm2 < b.quick_fit_mm2;
  });
  std::vector<int> parts;
  for (const Listed& other : kept) parts.push_back(other.part);
  return parts;
}

std::string Recognizer::decide(const ViewAnalysis& analysis, const ScenePoints& points,
                               ModelSurfaces& surfaces, RecognitionResult& result) const {
  const RecognitionCandidate* best = best_candidate(result.candidates);
  if (!best) return "no candidate view could be registered";

  // The winner is chosen among the candidates whose surface is seen by score and by the
  // two-way fit (the share of the scene it explains times the share of its surface the scene
  // shows), among the sizes of one shape by the fit alone (size_variants.hpp); the rival is
  // the best such candidate of another part (part_ambiguity.hpp).
  const RecognitionCandidate* rival = nullptr;
  // The best candidate of another shape, when the rival is another size of the winner's: sizes
  // are told apart by their fits, which says nothing of a part of another shape that explains
  // the scene as well.
  const RecognitionCandidate* shape_rival = nullptr;
  const RecognitionCandidate* winner = nullptr;
  bool best_at_rest = true;
  // A candidate is only as good as its placed surface is seen in the scene (surface_seen.hpp):
  // one that puts surface where the scanner saw none explains the scene's points by chance.
  const auto qualifies = [&](const RecognitionCandidate& candidate) {
    return at_rest(candidate) && candidate.seen_fraction >= parameters_.min_seen_fraction;
  };
  const auto choose = [&] {
    winner = rival = shape_rival = nullptr;
    for (RecognitionCandidate& candidate : result.candidates)
      candidate.qualified = candidate.registered && qualifies(candidate);
    best = best_candidate(result.candidates);
    result.seen_fraction = best->seen_fraction;
    best_at_rest = at_rest(*best);
    const std::vector<const RecognitionCandidate*> ranked = ranked_candidates(result.candidates);
    // A part that contains the scene (a plate under a bracket's face) explains its points as
    // well as the scene's own part, and puts surface where the scanner saw the belt: among
    // candidates scoring alike, the one fitting better both ways wins.
    winner = score_or_fit_winner(ranked, parameters_.ambiguity.examined_score_margin,
                                 parameters_.ambiguity.two_way_fit_margin);
    if (winner && parameters_.size_variants.search &&
        !size_variants_[static_cast<std::size_t>(winner->part)].empty()) {
      const int family_part = winner->part;
      double best_fit = two_way_fit(*winner);
      for (const RecognitionCandidate* candidate : ranked)
        if (is_size_variant(family_part, candidate->part) && candidate->qualified &&
            two_way_fit(*candidate) > best_fit) {
          best_fit = two_way_fit(*candidate);
          winner = candidate;
        }
    }
    if (!winner) return;
    result.seen_fraction = winner->seen_fraction;
    // The best other size of the winner's shape, when one qualifies, is its rival: the two
    // are told apart by their two-way fits, which a third part scoring higher cannot settle.
    for (bool sizes_only : {true, false}) {
      for (const RecognitionCandidate* candidate : ranked)
        if (candidate->part != winner->part && candidate->qualified &&
            (!sizes_only || is_size_variant(winner->part, candidate->part))) {
          rival = candidate;
          break;
        }
      if (rival) break;
    }
    if (rival) result.runner_up_seen_fraction = rival->seen_fraction;
    for (const RecognitionCandidate* candidate : ranked)
      if (candidate->part != winner->part && candidate->qualified &&
          !is_size_variant(winner->part, candidate->part)) {
        shape_rival = candidate;
        break;
      }
  };
  choose();
  // A rival only verified on one selected view may have registered far from its best pose;
  // the pose search over its part's views gives it its fair chance before it is compared. So
  // do the other sizes of the winner's shape, which selection cannot tell from it; and, when
  // no candidate qualifies, the other sizes of the best one's: a larger size fitted to a
  // smaller one's scene reaches through the belt or puts surface where the scene has none,
  // and the search, which stops at the first part that explains the scene, never reached the
  // size that would have rested.
  const auto pose_searched = [&](int part) {
    return std::any_of(result.candidates.begin(), result.candidates.end(),
                       [part](const RecognitionCandidate& c) {
                         return c.part == part && c.searched_over_views();
                       });
  };
  // Unless the search over every part found its quick fit hopeless beside the best full fit
  // there: as in that search, its full stages would rarely lower the fit that much, and the
  // search left every part ranked behind it unsearched for that reason.
  const auto hopeless = [&](int part) {
    const auto quick = std::find_if(result.quick_fits.begin(), result.quick_fits.end(),
                                    [part](const QuickFieldFit& fit) { return fit.part == part; });
    return quick != result.quick_fits.end() &&
           quick->fit_mm2 > parameters_.search.worst_kept_score_mm2(result.best_field_fit_mm2);
  };
  std::vector<int> unsearched;
  for (const RecognitionCandidate* compared : {rival, shape_rival})
    if (compared && parameters_.ambiguity.search_rival_part && !pose_searched(compared->part) &&
        std::find(unsearched.begin(), unsearched.end(), compared->part) == unsearched.end()) {
      const bool left = hopeless(compared->part);
      if (compared == rival) result.rival_left_unsearched = left;
      if (!left) unsearched.push_back(compared->part);
    }
  const RecognitionCandidate* family_of = winner ? winner : best;
  const auto search_too = [&](int part) {
    if (!pose_searched(part) &&
        std::find(unsearched.begin(), unsearched.end(), part) == unsearched.end())
      unsearched.push_back(part);
  };
  // The other sizes are registered from the poses of this one (size_variants.hpp).
  std::vector<int> scaled_sizes;
  if (parameters_.size_variants.search)
    for (int variant : size_variants_[static_cast<std::size_t>(family_of->part)]) {
      if (!parameters_.size_variants.from_winner_poses)
        search_too(variant);
      else if (!pose_searched(variant) &&
               std::find(unsearched.begin(), unsearched.end(), variant) == unsearched.end())
        scaled_sizes.push_back(variant);
    }
  // So do the parts the base lists as confusable with the winner's (one of them explains a view
  // of the other as closely as its own part): the search ended at the winner, and the scene's
  // own part may be one of them that ranked lower.
  const auto queued = [&](int part) {
    return pose_searched(part) ||
           std::find(unsearched.begin(), unsearched.end(), part) != unsearched.end() ||
           std::find(scaled_sizes.begin(), scaled_sizes.end(), part) != scaled_sizes.end();
  };
  if (parameters_.confusable.search) {
    std::vector<int> confusable =
        confusable_parts_unsearched(family_of->part, points, result, queued);
    if (confusable.size() > static_cast<std::size_t>(parameters_.confusable.searched_parts))
      confusable.resize(static_cast<std::size_t>(parameters_.confusable.searched_parts));
    for (int part : confusable) {
      unsearched.push_back(part);
      result.confusable_parts_searched.push_back(part);
    }
  }
  if (!unsearched.empty() || !scaled_sizes.empty()) {
    const int posed_part = family_of->part;
    for (int part : scaled_sizes)
      register_scaled_size(analysis, points, surfaces, part, posed_part, result);
    // One part at a time: a search stops at the first part that explains the scene.
    for (int part : unsearched) search_candidate_parts(analysis, points, surfaces, result, {part});
    choose();
  }
  const bool none_seen = winner == nullptr;
  if (winner) best = winner;

  result.part = best->part;
  result.view = best->view;
  result.best_candidate_part = best->part;
  result.score = best->score;
  result.spectral_distance = best->spectral_distance;
  result.registration_rms_mm = best->rms_mm;
  result.inlier_fraction = best->inlier_fraction;
  if (rival) {
    result.runner_up_part = rival->part;
    result.runner_up_score = rival->score;
  }
  const ModelBaseView& view = model_base_.views[static_cast<std::size_t>(best->view)];
  result.T_scanner_part = (best->T_model_scene.inverse() * view.T_scanner_part).normalized();
  if (none_seen && !best_at_rest) {
    result.part = -1;
    const RestingCheck rest = check_resting(*best);
    char numbers[128];
    if (rest.touches_belt)
      std::snprintf(numbers, sizeof numbers,
                    "does not rest on the belt: %.0f deg from its part's nearest resting pose",
                    rest.tilt_deg);
    else
      std::snprintf(numbers, sizeof numbers,
                    "does not touch the belt: its lowest point %.1f mm above it",
                    rest.lowest_point_mm);
    return std::string("best candidate ") + numbers;
  }
  if (none_seen) {
    result.part = -1;
    return "best candidate's surface is not where the scene is: " +
           std::to_string(static_cast<int>(std::lround(100 * result.seen_fraction))) +
           " % of it seen";
  }
  if (best->searched_over_views() && best->seen_fraction < parameters_.min_accepted_seen_fraction) {
    result.part = -1;
    return "only " + std::to_string(static_cast<int>(std::lround(100 * best->seen_fraction))) +
           " % of the best candidate's surface is where the scene is";
  }
  if (best->inlier_fraction < parameters_.min_inlier_fraction) {
    result.part = -1;
    return "best candidate explains only " +
           std::to_string(static_cast<int>(100 * best->inlier_fraction)) + " % of the surface";
  }
  if (best->rms_mm > parameters_.max_rms_mm) {
    result.part = -1;
    return "best candidate's registration residual is too large";
  }
  if (best->seen_fraction < parameters_.confusable.min_seen_fraction) {
    const std::size_t left = confusable_parts_unsearched(best->part, points, result, queued).size();
    if (left > 0) {
      result.part = -1;
      return "ambiguous: only " +
             std::to_string(static_cast<int>(std::lround(100 * best->seen_fraction))) +
             " % of the best candidate's surface is where the scene is, with parts it may be "
             "taken for left unsearched: " +
             std::to_string(left);
    }
  }
  const std::vector<int> close_parts =
      close_fitting_parts(result.quick_fits, parameters_.ambiguity.close_fit_mm2);
  const auto uncompared = std::count_if(close_parts.begin(), close_parts.end(), [&](int part) {
    return std::none_of(
        result.candidates.begin(), result.candidates.end(),
        [part](const RecognitionCandidate& c) { return c.part == part && c.registered; });
  });
  if (uncompared > parameters_.ambiguity.max_uncompared_close_parts) {
    result.part = -1;
    return "ambiguous: " + std::to_string(uncompared) +
           " parts never compared with the best fit the scene as closely";
  }
  const auto percent = [](double fraction) {
    return std::to_string(static_cast<int>(std::lround(100 * fraction)));
  };
  const auto part_name = [this](int part) {
    return model_base_.parts[static_cast<std::size_t>(part)].name;
  };
  // Score and fit both ways must name the same part (part_ambiguity.hpp).
  const std::vector<const RecognitionCandidate*> ranked = ranked_candidates(result.candidates);
  if (const RecognitionCandidate* contesting = contesting_candidate(
          ranked, *best, parameters_.ambiguity.two_way_fit_margin,
          parameters_.ambiguity.two_way_fit_noise,
          [&](int part) { return part != best->part && !is_size_variant(best->part, part); })) {
    result.part = -1;
    result.other_shape_part = contesting->part;
    char figures[96];
    std::snprintf(figures, sizeof figures,
                  "scores %.2f and %.2f, fit both ways %.0f %% and %.0f %%", best->score,
                  contesting->score, 100 * two_way_fit(*best), 100 * two_way_fit(*contesting));
    return "ambiguous between " + part_name(best->part) + " and " + part_name(contesting->part) +
           ": score and fit name different parts (" + figures + ")";
  }
  // Sizes of one shape are told apart by the two-way fit, which the ambiguity test (the scene's
  // points alone) cannot see: a larger size explains a smaller one's scene as well. So sizes
  // whose fits differ by registration noise alone are not told apart at all.
  const double fit_noise = parameters_.ambiguity.two_way_fit_noise;
  if (parameters_.size_variants.search)
    if (const RecognitionCandidate* size =
            contesting_candidate(ranked, *best, fit_noise, -fit_noise,
                                 [&](int part) { return is_size_variant(best->part, part); })) {
      result.part = -1;
      result.runner_up_part = size->part;
      result.runner_up_score = size->score;
      result.size_fit = two_way_fit(*best);
      result.runner_up_size_fit = two_way_fit(*size);
      // Reported as an ambiguity with that size: the evaluation counts the sizes not told apart.
      result.ambiguity.ambiguous = true;
      return "ambiguous between " + part_name(best->part) + " and " + part_name(size->part) +
             ": sizes of one shape that fit alike both ways (" + percent(result.size_fit) +
             " % and " + percent(result.runner_up_size_fit) + " %)";
    }
  const bool sizes_told_apart =
      rival && is_size_variant(best->part, rival->part) && parameters_.size_variants.search &&
      two_way_fit(*best) - two_way_fit(*rival) >= parameters_.size_variants.fit_margin;
  if (rival && is_size_variant(best->part, rival->part)) {
    result.size_fit = two_way_fit(*best);
    result.runner_up_size_fit = two_way_fit(*rival);
  }
  // The rival, unless sizes told apart, and the best part of another shape are each examined
  // where they differ from the winner when they score close to it.
  const RecognitionCandidate* other_shape = shape_rival == rival ? nullptr : shape_rival;
  if (other_shape) result.other_shape_part = other_shape->part;
  for (const RecognitionCandidate* compared : {sizes_told_apart ? nullptr : rival, other_shape}) {
    if (!compared || best->score - compared->score >= parameters_.ambiguity.examined_score_margin)
      continue;
    result.ambiguity_examined = true;
    result.ambiguity = judge_part_ambiguity(
        points.all, model_base_,
        {best->view, best->T_model_scene, best->seen_fraction, part_search_model(best->part).views},
        {compared->view, compared->T_model_scene, compared->seen_fraction,
         part_search_model(compared->part).views},
        parameters_.registration, parameters_.support, parameters_.ambiguity, surfaces);
    if (result.ambiguity.ambiguous) {
      result.part = -1;
      return "ambiguous between " + part_name(best->part) + " and " + part_name(compared->part) +
             ": " + percent(result.ambiguity.discriminating_fraction) +
             " % of scene and surfaces tell them apart, " +
             percent(result.ambiguity.discriminating_share) + " % of it for the first";
    }
  }
  RecognitionCandidate refined = *best;
  if (refine_free_motion(points, surfaces, refined)) {
    result.free_motion_refined = true;
    result.T_scanner_part = (refined.T_model_scene.inverse() * view.T_scanner_part).normalized();
    result.score = refined.score;
    result.registration_rms_mm = refined.rms_mm;
    result.inlier_fraction = refined.inlier_fraction;
  }
  // On the score reported: the pose along the free motion is the one published.
  if (result.score < parameters_.min_score) {
    result.part = -1;
    char score[16];
    std::snprintf(score, sizeof score, "%.2f", result.score);
    return std::string("best candidate fits too loosely: score ") + score;
  }
  result.status = RecognitionStatus::kOk;
  return "";
}

}  // namespace cosmos
