#include "core/recognition/ranked_candidates.hpp"

#include <algorithm>

namespace cosmos {

const RecognitionCandidate* best_candidate(const std::vector<RecognitionCandidate>& candidates) {
  const RecognitionCandidate* best = nullptr;
  for (const RecognitionCandidate& candidate : candidates)
    if (candidate.registered && (!best || candidate.score > best->score)) best = &candidate;
  return best;
}

std::vector<const RecognitionCandidate*> ranked_candidates(
    const std::vector<RecognitionCandidate>& candidates) {
  std::vector<const RecognitionCandidate*> ranked;
  for (const RecognitionCandidate& candidate : candidates)
    if (candidate.registered) ranked.push_back(&candidate);
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const RecognitionCandidate* a, const RecognitionCandidate* b) {
                     return a->score > b->score;
                   });
  return ranked;
}

double two_way_fit(const RecognitionCandidate& candidate) {
  return candidate.inlier_fraction * candidate.seen_fraction;
}

const RecognitionCandidate* score_or_fit_winner(
    const std::vector<const RecognitionCandidate*>& ranked, double examined_score_margin,
    double two_way_fit_margin) {
  const RecognitionCandidate* top = nullptr;
  const RecognitionCandidate* best_fit = nullptr;
  for (const RecognitionCandidate* candidate : ranked) {
    if (!candidate->qualified) continue;
    if (!top) top = candidate;
    if (top->score - candidate->score < examined_score_margin &&
        (!best_fit || two_way_fit(*candidate) > two_way_fit(*best_fit)))
      best_fit = candidate;
  }
  if (best_fit && two_way_fit(*best_fit) > two_way_fit(*top) + two_way_fit_margin) return best_fit;
  return top;
}

const RecognitionCandidate* contesting_candidate(
    const std::vector<const RecognitionCandidate*>& ranked, const RecognitionCandidate& winner,
    double two_way_fit_margin, double max_fit_deficit, const std::function<bool(int)>& compared) {
  const RecognitionCandidate* contesting = nullptr;
  std::vector<int> parts_weighed;
  for (const RecognitionCandidate* candidate : ranked) {
    if (!candidate->qualified || !compared(candidate->part) ||
        std::find(parts_weighed.begin(), parts_weighed.end(), candidate->part) !=
            parts_weighed.end())
      continue;
    parts_weighed.push_back(candidate->part);
    const double lead = two_way_fit(winner) - two_way_fit(*candidate);
    const bool contests =
        candidate->score > winner.score ? lead <= two_way_fit_margin : -lead > max_fit_deficit;
    if (contests && (!contesting || two_way_fit(*candidate) > two_way_fit(*contesting)))
      contesting = candidate;
  }
  return contesting;
}

}  // namespace cosmos
