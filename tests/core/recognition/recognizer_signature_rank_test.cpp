// The signature rank (signature_rank.hpp) in the recognizer's search over every part, against
// the regression model base (recognizer_fixture.hpp): the parts quick-fitted first, those left
// out, and the tiers fitted when none of the first fits closely.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/recognition/recognizer.hpp"
#include "tests/core/recognition/recognizer_fixture.hpp"

namespace cosmos {
namespace {

// The search over every part quick-fits first only the part of closest signature and those
// within `ratio` of it, and the others tier_parts at a time.
RecognitionParameters closest_signature_first(double ratio, int tier_parts) {
  RecognitionParameters parameters;
  parameters.views_before_search = 0;
  parameters.resting.parts_touch_belt = true;
  parameters.signature_rank.min_parts = 1;
  parameters.signature_rank.ratio = ratio;
  parameters.signature_rank.tier_parts = tier_parts;
  return parameters;
}

// A seeded scene of one of the base's parts that a recognizer searched over every part, with
// its result and the result of a search that quick-fits every part.
struct SearchedScene {
  std::uint64_t seed = 0;
  int own_part = -1;
  RangeImage image;
  RecognitionResult result;
  RecognitionResult every_part;
};

// Of 20 seeded scenes, those `recognizer` searched over every part (whose quick fits are not
// empty). In each, the parts fitted and those left out by signature are the parts `every_part`
// fits.
std::vector<SearchedScene> searched_scenes(
    const Recognizer& recognizer, const Recognizer& every_part, const ModelBase& base,
    const std::function<RangeImage(const std::string&, std::uint64_t)>& scan_of) {
  std::vector<SearchedScene> scenes;
  for (std::uint64_t seed = 41; seed < 61; ++seed) {
    SearchedScene scene;
    scene.seed = seed;
    scene.own_part = static_cast<int>(seed % base.parts.size());
    scene.image = scan_of(base.parts[static_cast<std::size_t>(scene.own_part)].name, seed);
    scene.result = recognizer.recognize(scene.image);
    if (scene.result.quick_fits.empty()) continue;
    scene.every_part = every_part.recognize(scene.image);
    EXPECT_EQ(scene.result.quick_fits.size() +
                  static_cast<std::size_t>(scene.result.parts_left_out_by_signature),
              scene.every_part.quick_fits.size())
        << seed;
    scenes.push_back(std::move(scene));
  }
  return scenes;
}

// The signature rank (signature_rank.hpp) quick-fits first the parts whose views' signatures
// lie closest to the scene's. Told to fit first only the closest part and those nearly as close,
// and the others all at once when none of those fits closely, the search leaves the other parts
// out only when one of those fits closely, and then the scene is identified as it is with every
// part quick-fitted; a scene that may hold several parts, or parts that may not lie on the belt,
// leave none out.
TEST_F(RecognizerOnRegressionBase, TheSearchOverEveryPartFitsThePartsOfClosestSignatureFirst) {
  const RecognitionParameters parameters = closest_signature_first(1.2, 1000);
  RecognitionParameters every_part = parameters;
  every_part.signature_rank.enabled = false;
  RecognitionParameters off_belt = parameters;
  off_belt.resting.parts_touch_belt = false;
  const Recognizer recognizer(*base_, CosmosParameters{}, parameters);
  const Recognizer off_belt_recognizer(*base_, CosmosParameters{}, off_belt);
  const std::vector<SearchedScene> scenes =
      searched_scenes(recognizer, Recognizer(*base_, CosmosParameters{}, every_part), *base_, scan);
  int with_parts_left_out = 0, identified = 0;
  for (const SearchedScene& scene : scenes) {
    const RecognitionResult& result = scene.result;
    const std::uint64_t seed = scene.seed;
    EXPECT_EQ(scene.every_part.parts_left_out_by_signature, 0) << seed;
    if (result.parts_left_out_by_signature > 0) {
      ++with_parts_left_out;
      EXPECT_TRUE(std::any_of(result.quick_fits.begin(), result.quick_fits.end(),
                              [&](const QuickFieldFit& fit) {
                                return fit.on_belt &&
                                       fit.fit_mm2 <= parameters.signature_rank.fit_mm2;
                              }))
          << seed;
      EXPECT_FALSE(result.catalog_searched) << seed;
    }
    EXPECT_EQ(result.status, scene.every_part.status) << seed;
    EXPECT_EQ(result.part, scene.every_part.part) << seed;
    identified += result.status == RecognitionStatus::kOk && result.part == scene.own_part ? 1 : 0;
    EXPECT_EQ(recognizer.recognize(scene.image, SceneParts::kOneOrMore).parts_left_out_by_signature,
              0)
        << seed;
    EXPECT_EQ(off_belt_recognizer.recognize(scene.image).parts_left_out_by_signature, 0) << seed;
  }
  const int searched = static_cast<int>(scenes.size());
  std::printf("%d scenes searched, %d with parts left out, %d identified\n", searched,
              with_parts_left_out, identified);
  EXPECT_GE(searched, 15);
  EXPECT_GE(with_parts_left_out, 5);
  EXPECT_GE(identified, searched - 2);
}

// When none of the parts fitted first fits closely, the others are fitted a tier at a time while
// each tier fits better than all before: with tiers of one part, some scenes stop before every
// part is fitted though none fits closely. Each part fitted has the quick fit it has when every
// part is, and the scenes are identified as when every part is fitted.
TEST_F(RecognizerOnRegressionBase, WhenNoneFitsCloselyTheOthersAreFittedInTiersWhileTheyFitBetter) {
  RecognitionParameters parameters = closest_signature_first(1.0, 1);
  parameters.signature_rank.fit_mm2 = 0;
  RecognitionParameters every_part = parameters;
  every_part.signature_rank.enabled = false;
  const std::vector<SearchedScene> scenes =
      searched_scenes(Recognizer(*base_, CosmosParameters{}, parameters),
                      Recognizer(*base_, CosmosParameters{}, every_part), *base_, scan);
  int stopped = 0, same = 0;
  for (const SearchedScene& scene : scenes) {
    const std::vector<QuickFieldFit>& all = scene.every_part.quick_fits;
    for (const QuickFieldFit& fit : scene.result.quick_fits) {
      const auto reference = std::find_if(all.begin(), all.end(), [&](const QuickFieldFit& other) {
        return other.part == fit.part;
      });
      ASSERT_NE(reference, all.end()) << scene.seed;
      EXPECT_EQ(fit.fit_mm2, reference->fit_mm2) << scene.seed;
    }
    stopped += scene.result.parts_left_out_by_signature > 0 ? 1 : 0;
    same +=
        scene.result.status == scene.every_part.status && scene.result.part == scene.every_part.part
            ? 1
            : 0;
  }
  EXPECT_GE(scenes.size(), 15u);
  EXPECT_GE(stopped, 3);
  EXPECT_GE(same, static_cast<int>(scenes.size()) - 2);
}

}  // namespace
}  // namespace cosmos
