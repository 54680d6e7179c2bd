// The order the decision weighs registered candidates in, its winner among candidates scoring
// alike, and the candidates contesting a winner (ranked_candidates.hpp), on hand-made
// candidates.
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

const auto any_other_part = [](int part) { return part != 0; };

TEST(RankedCandidates, APartFittingBetterBothWaysContestsAWinnerOfHigherScore) {
  // The winner scores 0.85 and fits 0.90 x 0.90 = 0.81; the other scores 0.80 and fits 0.855.
  const std::vector<RecognitionCandidate> candidates = {candidate(0, 0.85, 0.90, 0.90),
                                                        candidate(1, 0.80, 0.90, 0.95)};
  const RecognitionCandidate* contesting = contesting_candidate(
      ranked_candidates(candidates), candidates[0], kFitMargin, 0.0, any_other_part);
  ASSERT_NE(contesting, nullptr);
  EXPECT_EQ(contesting->part, 1);
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], kFitMargin, 0.05,
                                 any_other_part),
            nullptr);
}

TEST(RankedCandidates, AWinnerByFitMustOutfitEveryHigherScoreByTheMargin) {
  // The winner fits 0.92; the higher-scored fits 0.84 (0.08 behind), then 0.81 (0.11 behind).
  std::vector<RecognitionCandidate> candidates = {candidate(0, 0.70, 0.92, 1.00),
                                                  candidate(1, 0.74, 0.84, 1.00)};
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], kFitMargin, 0.0,
                                 any_other_part),
            &candidates[1]);
  candidates[1].inlier_fraction = 0.81;
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], kFitMargin, 0.0,
                                 any_other_part),
            nullptr);
}

TEST(RankedCandidates, OnlyQualifiedCandidatesOfComparedPartsContest) {
  std::vector<RecognitionCandidate> candidates = {candidate(0, 0.85, 0.90, 0.90),
                                                  candidate(0, 0.80, 1.00, 1.00),
                                                  candidate(1, 0.80, 1.00, 1.00)};
  candidates[2].qualified = false;
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], kFitMargin, 0.0,
                                 any_other_part),
            nullptr);
  candidates[2].qualified = true;
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], kFitMargin, 0.0,
                                 any_other_part),
            &candidates[2]);
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], kFitMargin, 0.0,
                                 [](int) { return false; }),
            nullptr);
}

TEST(RankedCandidates, APartContestsByItsBestScoredCandidateAlone) {
  // Part 1's best-scored candidate fits 0.50; its other, fitting 0.95, scores below it.
  std::vector<RecognitionCandidate> candidates = {candidate(0, 0.85, 0.90, 0.90),
                                                  candidate(1, 0.80, 0.50, 1.00),
                                                  candidate(1, 0.60, 0.95, 1.00)};
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], kFitMargin, 0.0,
                                 any_other_part),
            nullptr);
  candidates[1].qualified = false;
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], kFitMargin, 0.0,
                                 any_other_part),
            &candidates[2]);
}

TEST(RankedCandidates, EqualFitsOfALowerScoreDoNotContest) {
  const std::vector<RecognitionCandidate> candidates = {candidate(0, 0.90, 1.00, 1.00),
                                                        candidate(1, 0.80, 1.00, 1.00)};
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], kFitMargin, 0.0,
                                 any_other_part),
            nullptr);
}

// As sizes of one shape are weighed: the winner outfits each of them by the margin, or they
// contest it (a deficit of minus the margin).
TEST(RankedCandidates, ANegativeDeficitIsALeadTheWinnerMustHaveOverLowerScores) {
  std::vector<RecognitionCandidate> candidates = {candidate(0, 0.90, 0.95, 1.00),
                                                  candidate(1, 0.80, 0.93, 1.00)};
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], 0.03, -0.03,
                                 any_other_part),
            &candidates[1]);
  candidates[1].inlier_fraction = 0.91;
  EXPECT_EQ(contesting_candidate(ranked_candidates(candidates), candidates[0], 0.03, -0.03,
                                 any_other_part),
            nullptr);
}

}  // namespace
}  // namespace cosmos
