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

}  // namespace cosmos
