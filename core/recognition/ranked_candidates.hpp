#pragma once
// The recognizer's registered candidates in the order the decision weighs them (recognizer.hpp):
// by score, the figure of merit of support, residual and COSMOS match together.
#include <functional>
#include <vector>

#include "core/recognition/recognizer.hpp"

namespace cosmos {

// The registered candidate with the highest score (the first verified among equals); nullptr
// when none registered.
const RecognitionCandidate* best_candidate(const std::vector<RecognitionCandidate>& candidates);

// Registered candidates, best score first (ties: the order they were verified in).
std::vector<const RecognitionCandidate*> ranked_candidates(
    const std::vector<RecognitionCandidate>& candidates);

// How well a candidate fits both ways: the share of the scene's points on its surface times
// the share of its placed view where the scene is (surface_seen.hpp).
double two_way_fit(const RecognitionCandidate& candidate);

// The winner among the qualified candidates of `ranked` (best score first): the best-scored,
// unless one scoring within examined_score_margin of it fits better both ways by
// two_way_fit_margin. Then the one of those that fits best both ways wins: each is weighed
// against the best-scored, not against whichever outweighed it before, so the order of their
// scores, which differ by registration noise, does not choose among them. nullptr when none
// qualified.
const RecognitionCandidate* score_or_fit_winner(
    const std::vector<const RecognitionCandidate*>& ranked, double examined_score_margin,
    double two_way_fit_margin);

// Among the qualified candidates of `ranked` (best score first), each part of those `compared`
// accepts by its best-scored one, as a rival stands: the one contesting `winner`, fitting the
// scene better both ways by more than max_fit_deficit, or scoring higher and fitting within
// two_way_fit_margin of it both ways (a winner that outweighed higher scores by its fit,
// score_or_fit_winner, leads each of them by the margin, not only the best-scored). The
// best-fitting such one; nullptr when none.
const RecognitionCandidate* contesting_candidate(
    const std::vector<const RecognitionCandidate*>& ranked, const RecognitionCandidate& winner,
    double two_way_fit_margin, double max_fit_deficit, const std::function<bool(int)>& compared);

}  // namespace cosmos
