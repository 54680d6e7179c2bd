// The recognizer's decision (recognizer_decision.cpp) against the regression model base
// (recognizer_fixture.hpp): the rival it compares the winner with.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/recognition/recognizer.hpp"
#include "tests/core/recognition/recognizer_fixture.hpp"

namespace cosmos {
namespace {

bool part_pose_searched(const RecognitionResult& result, int part) {
  return std::any_of(
      result.candidates.begin(), result.candidates.end(),
      [part](const RecognitionCandidate& c) { return c.part == part && c.from_pose_search; });
}

// A rival only verified on a selected view is searched over its part's views before it is
// compared, unless the search over every part found its quick fit hopeless beside the best
// full fit there (the rule that ended that search): then it is compared as registered, and no
// pose of its part comes from a search. With no fit hopeless (a huge kept-score factor) the
// same scans' rivals are searched.
TEST_F(RecognizerOnRegressionBase, ARivalWhoseQuickFitIsHopelessIsNotSearchedAgain) {
  const RecognitionParameters parameters;
  RecognitionParameters none_hopeless;
  none_hopeless.search.kept_score_factor = 1e6;
  const Recognizer searching_every_rival(*base_, CosmosParameters{}, none_hopeless);
  int left_unsearched = 0;
  for (std::uint64_t seed = 301; seed < 341; ++seed) {
    const std::string& name = base_->parts[seed % base_->parts.size()].name;
    const RangeImage image = scan(name, seed);
    const RecognitionResult result = recognizer_->recognize(image);
    if (!result.rival_left_unsearched) continue;
    ++left_unsearched;
    const int rival = result.runner_up_part;
    ASSERT_GE(rival, 0) << seed;
    const auto quick =
        std::find_if(result.quick_fits.begin(), result.quick_fits.end(),
                     [rival](const QuickFieldFit& fit) { return fit.part == rival; });
    ASSERT_NE(quick, result.quick_fits.end()) << seed;
    EXPECT_GT(quick->fit_mm2, parameters.search.worst_kept_score_mm2(result.best_field_fit_mm2))
        << seed;
    EXPECT_FALSE(part_pose_searched(result, rival)) << seed;
    const RecognitionResult searched = searching_every_rival.recognize(image);
    EXPECT_FALSE(searched.rival_left_unsearched) << seed;
    EXPECT_TRUE(part_pose_searched(searched, rival)) << seed;
  }
  EXPECT_GE(left_unsearched, 1);
}

}  // namespace
}  // namespace cosmos
