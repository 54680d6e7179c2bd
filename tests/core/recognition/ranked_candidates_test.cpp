// The order the decision weighs registered candidates in, and its winner among candidates
// scoring alike (ranked_candidates.hpp), on hand-made candidates.
#include "core/recognition/ranked_candidates.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cosmos {
namespace {

RecognitionCandidate candidate(int part, double score, double inlier_fraction,
                               double seen_fraction) {
  RecognitionCandidate c;
  c.part = part;
  c.registered = true;
  c.qualified = true;
  c.score = score;
  c.inlier_fraction = inlier_fraction;
  c.seen_fraction = seen_fraction;
  return c;
}

constexpr double kScoreMargin = 0.1;
constexpr double kFitMargin = 0.1;

TEST(RankedCandidates, BestScoreFirstAndTiesInVerificationOrder) {
  std::vector<RecognitionCandidate> candidates = {candidate(0, 0.5, 1, 1), candidate(1, 0.7, 1, 1),
                                                  candidate(2, 0.5, 1, 1), candidate(3, 0.9, 1, 1)};
  candidates[3].registered = false;
  const std::vector<const RecognitionCandidate*> ranked = ranked_candidates(candidates);
  ASSERT_EQ(ranked.size(), 3u);
  EXPECT_EQ(ranked[0]->part, 1);
  EXPECT_EQ(ranked[1]->part, 0);
  EXPECT_EQ(ranked[2]->part, 2);
  EXPECT_EQ(best_candidate(candidates)->part, 1);
}

TEST(RankedCandidates, TheTwoWayFitIsTheExplainedShareTimesTheSeenShare) {
  EXPECT_DOUBLE_EQ(two_way_fit(candidate(0, 0.5, 0.8, 0.5)), 0.4);
}

TEST(RankedCandidates, TheBestScoredWinsUnlessAnotherScoringAlikeFitsBetterBothWays) {
  std::vector<RecognitionCandidate> candidates = {candidate(0, 0.80, 0.90, 0.80),
                                                  candidate(1, 0.75, 0.95, 0.80)};
  EXPECT_EQ(score_or_fit_winner(ranked_candidates(candidates), kScoreMargin, kFitMargin)->part, 0);
  candidates[1].seen_fraction = 1.0;  // two-way fit 0.95 against 0.72
  EXPECT_EQ(score_or_fit_winner(ranked_candidates(candidates), kScoreMargin, kFitMargin)->part, 1);
  candidates[1].score = 0.65;  // no longer scoring alike
  EXPECT_EQ(score_or_fit_winner(ranked_candidates(candidates), kScoreMargin, kFitMargin)->part, 0);
}

// The best-scored fits 0.70 both ways; the second 0.84, better by more than the margin; the
// third 0.92, better than the second by less than the margin. Weighed in turn, the second would
// win and the third could not outweigh it; weighed against the best-scored, the third wins.
TEST(RankedCandidates, AmongThoseScoringAlikeTheOneFittingBestBothWaysWinsWhateverTheirOrder) {
  const std::vector<RecognitionCandidate> candidates = {candidate(0, 0.740, 0.90, 0.78),
                                                        candidate(1, 0.739, 0.87, 0.96),
                                                        candidate(2, 0.708, 0.92, 1.00)};
  EXPECT_EQ(score_or_fit_winner(ranked_candidates(candidates), kScoreMargin, kFitMargin)->part, 2);
}

TEST(RankedCandidates, OnlyQualifiedCandidatesWin) {
  std::vector<RecognitionCandidate> candidates = {candidate(0, 0.9, 0.9, 0.9),
                                                  candidate(1, 0.85, 0.95, 1.0)};
  candidates[0].qualified = false;
  EXPECT_EQ(score_or_fit_winner(ranked_candidates(candidates), kScoreMargin, kFitMargin)->part, 1);
  candidates[1].qualified = false;
  EXPECT_EQ(score_or_fit_winner(ranked_candidates(candidates), kScoreMargin, kFitMargin), nullptr);
}

}  // namespace
}  // namespace cosmos
