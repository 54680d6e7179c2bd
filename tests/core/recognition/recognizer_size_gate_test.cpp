// The size gate (part_size_gate.hpp) in the recognizer's search over every part, against the
// regression model base (recognizer_fixture.hpp): the parts left out before any is fitted, and
// what a scene that may hold several parts bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/recognition/recognizer.hpp"
#include "tests/core/recognition/recognizer_fixture.hpp"

namespace cosmos {
namespace {

// Whether the search over every part ranked `part` (did not leave it out by size).
bool ranked(const RecognitionResult& result, int part) {
  return std::any_of(result.quick_fits.begin(), result.quick_fits.end(),
                     [part](const QuickFieldFit& fit) { return fit.part == part; });
}

// The size gate (part_size_gate.hpp) leaves out of the search over every part only parts
// too small or too thick for the scene, never the scene's own; a scene that may hold several
// parts bounds no part's extent, and with the gate off every part is ranked.
TEST_F(RecognizerOnRegressionBase, TheSearchOverEveryPartLeavesOutOnlyPartsOfAnotherSize) {
  RecognitionParameters parameters;
  parameters.views_before_search = 0;
  parameters.resting.parts_touch_belt = true;
  RecognitionParameters ungated = parameters;
  ungated.size_gate.enabled = false;
  const Recognizer gated_recognizer(*base_, CosmosParameters{}, parameters);
  const Recognizer ungated_recognizer(*base_, CosmosParameters{}, ungated);
  const std::size_t part_count = base_->parts.size();
  int smaller = 0, thicker = 0, searched = 0;
  for (std::uint64_t seed = 41; seed < 61; ++seed) {
    const int own_part = static_cast<int>(seed % part_count);
    const RangeImage image = scan(base_->parts[static_cast<std::size_t>(own_part)].name, seed);
    const RecognitionResult gated = gated_recognizer.recognize(image);
    if (gated.quick_fits.empty()) continue;
    ++searched;
    EXPECT_EQ(gated.quick_fits.size() + static_cast<std::size_t>(gated.parts_smaller_than_scene +
                                                                 gated.parts_thicker_than_scene),
              part_count)
        << seed;
    EXPECT_TRUE(ranked(gated, own_part)) << seed;
    // A part left out is never registered by the search.
    for (const RecognitionCandidate& candidate : gated.candidates) {
      if (!candidate.from_pose_search) continue;
      EXPECT_TRUE(ranked(gated, candidate.part)) << seed;
    }
    smaller += gated.parts_smaller_than_scene;
    thicker += gated.parts_thicker_than_scene;

    const RecognitionResult several = gated_recognizer.recognize(image, SceneParts::kOneOrMore);
    EXPECT_EQ(several.parts_smaller_than_scene, 0) << seed;
    EXPECT_EQ(several.parts_thicker_than_scene, gated.parts_thicker_than_scene) << seed;
    const RecognitionResult all = ungated_recognizer.recognize(image);
    EXPECT_EQ(all.quick_fits.size(), part_count) << seed;
    EXPECT_EQ(all.parts_smaller_than_scene + all.parts_thicker_than_scene, 0) << seed;
  }
  EXPECT_GE(searched, 15);
  EXPECT_GE(smaller, 10);
  EXPECT_GE(thicker, 2);
}

// Two parts side by side in one scene (touching parts in one blob): told the scene holds one
// part, the gate leaves out the parts smaller than the pair, both of its own among them;
// told it may hold several, it bounds no part's extent.
TEST_F(RecognizerOnRegressionBase, TwoPartsSideBySideBoundNoPartsExtentWhenSeveralMayBeThere) {
  RecognitionParameters parameters;
  parameters.views_before_search = 0;
  parameters.resting.parts_touch_belt = true;
  const Recognizer recognizer(*base_, CosmosParameters{}, parameters);
  // Two of the base's parts, each narrower than the pair.
  const std::vector<int> own_parts = {4, 3};
  const RangeImage left = scan(base_->parts[static_cast<std::size_t>(own_parts[0])].name, 42);
  const RangeImage right = scan(base_->parts[static_cast<std::size_t>(own_parts[1])].name, 43);
  ASSERT_EQ(left.pixel_size_x_mm, right.pixel_size_x_mm);
  ASSERT_EQ(left.pixel_size_y_mm, right.pixel_size_y_mm);
  RangeImage pair(left.width() + right.width(), std::max(left.height(), right.height()),
                  left.pixel_size_x_mm, left.pixel_size_y_mm);
  pair.origin_x_mm = left.origin_x_mm;
  pair.origin_y_mm = left.origin_y_mm;
  pair.belt_seen = PixelGrid<std::uint8_t>(pair.width(), pair.height(), 0);
  for (int row = 0; row < pair.height(); ++row)
    for (int column = 0; column < pair.width(); ++column) {
      const bool on_left = column < left.width();
      const RangeImage& from = on_left ? left : right;
      const int from_column = on_left ? column : column - left.width();
      if (row >= from.height()) continue;
      pair.z_mm(column, row) = from.z_mm(from_column, row);
      if (from.belt_known()) pair.belt_seen(column, row) = from.belt_seen(from_column, row);
    }
  const RecognitionResult as_one = recognizer.recognize(pair, SceneParts::kOne);
  const RecognitionResult as_several = recognizer.recognize(pair, SceneParts::kOneOrMore);
  ASSERT_FALSE(as_several.quick_fits.empty());
  EXPECT_GE(as_one.parts_smaller_than_scene, 2);
  EXPECT_EQ(as_several.parts_smaller_than_scene, 0);
  for (const int part : own_parts) {
    EXPECT_FALSE(ranked(as_one, part)) << part;
    EXPECT_TRUE(ranked(as_several, part)) << part;
  }
}

}  // namespace
}  // namespace cosmos
