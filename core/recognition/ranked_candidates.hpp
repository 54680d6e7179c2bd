#pragma once
// The recognizer's registered candidates in the order the decision weighs them (recognizer.hpp):
// by score, the figure of merit of support, residual and COSMOS match together.
#include <vector>

#include "core/recognition/recognizer.hpp"

namespace cosmos {

// The registered candidate with the highest score (the first verified among equals); nullptr
// when none registered.
const RecognitionCandidate* best_candidate(const std::vector<RecognitionCandidate>& candidates);

// Registered candidates, best score first (ties: the order they were verified in).
std::vector<const RecognitionCandidate*> ranked_candidates(
    const std::vector<RecognitionCandidate>& candidates);

}  // namespace cosmos
