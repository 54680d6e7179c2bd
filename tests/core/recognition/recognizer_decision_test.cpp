// The recognizer's decision (recognizer_decision.cpp): the rival it compares the winner with,
// the winner's confusable parts it searches and the view it asks of a winner with some left
// unsearched, against the regression model base
// (recognizer_fixture.hpp); the other sizes it searches
// when no candidate qualifies, against a base of two shapes at three sizes each; and the
// winner and its rivals among flat-faced parts of three shapes at three sizes each.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "core/recognition/ranked_candidates.hpp"
#include "core/recognition/recognizer.hpp"
#include "sim/model_base_build/model_base_builder.hpp"
#include "tests/core/recognition/recognizer_fixture.hpp"

namespace cosmos {
namespace {

// The catalog of hundreds of parts, with its size families.
PartCatalog large_catalog() {
  return read_part_catalog(std::filesystem::path(COSMOS_SOURCE_DIR) / "config/parts-250.yaml");
}

// A base of the named catalog parts, 80 views each.
ModelBase family_base(const PartCatalog& catalog, const std::vector<std::string>& names) {
  PartCatalog families;
  for (const std::string& name : names) families.parts.push_back(catalog.at(name));
  ModelBaseBuildSettings settings;
  settings.view_count = 80;
  settings.threads = 2;
  return build_model_base(families, ScannerParameters{}, settings);
}

// The regression base with one confusable list, the cow's, holding the mannequin (larger than
// any view of the cow, so never left out by size).
struct CowListingMannequin {
  ModelBase base;
  int cow = -1;
  int mannequin = -1;
};

CowListingMannequin cow_listing_mannequin(const ModelBase& regression) {
  CowListingMannequin listed{regression};
  for (std::size_t part = 0; part < regression.parts.size(); ++part) {
    if (regression.parts[part].name == "cow") listed.cow = static_cast<int>(part);
    if (regression.parts[part].name == "mannequin-devil") listed.mannequin = static_cast<int>(part);
  }
  for (ModelPart& part : listed.base.parts) part.confusable_parts.clear();
  if (listed.cow >= 0 && listed.mannequin >= 0)
    listed.base.parts[static_cast<std::size_t>(listed.cow)].confusable_parts = {listed.mannequin};
  return listed;
}

// The part alone on the belt at a seeded random rotation, with seeded noise.
RangeImage scan_part(const PartEntry& part, std::uint64_t seed) {
  ScannerParameters scanner;
  scanner.seed = seed;
  return scan_single_part(load_mesh(part.mesh_path, part.size_mm), part.name, random_rotation(seed),
                          scanner, ConditioningParameters{});
}

// Searched over its views, or registered from another size's poses in the search's stead.
bool part_pose_searched(const RecognitionResult& result, int part) {
  return std::any_of(
      result.candidates.begin(), result.candidates.end(),
      [part](const RecognitionCandidate& c) { return c.part == part && c.searched_over_views(); });
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

// The winner's confusable parts (confusable_parts.hpp) are searched before the decision, at
// most confusable.searched_parts of them: a cow whose list holds the mannequin, which is
// larger than any view of the cow and so never left out by size, has the mannequin searched
// in every scan no other search reached it in, and is still named. With none to search, the
// decision searches none.
TEST_F(RecognizerOnRegressionBase, TheWinnersConfusablePartsAreSearchedBeforeTheDecision) {
  const CowListingMannequin listing = cow_listing_mannequin(*base_);
  const int cow = listing.cow, mannequin = listing.mannequin;
  ASSERT_GE(cow, 0);
  ASSERT_GE(mannequin, 0);
  const ModelBase& listed = listing.base;
  const Recognizer searching(listed, CosmosParameters{}, RecognitionParameters{});
  RecognitionParameters none_searched;
  none_searched.confusable.searched_parts = 0;
  const Recognizer not_searching(listed, CosmosParameters{}, none_searched);
  int named = 0, searched = 0;
  for (std::uint64_t seed = 401; seed < 409; ++seed) {
    const RangeImage image = scan("cow", seed);
    const RecognitionResult result = searching.recognize(image);
    const RecognitionResult plain = not_searching.recognize(image);
    EXPECT_TRUE(plain.confusable_parts_searched.empty()) << seed;
    if (plain.part != cow) continue;
    ++named;
    EXPECT_EQ(result.part, cow) << seed;
    if (part_pose_searched(plain, mannequin)) continue;
    ++searched;
    EXPECT_EQ(result.confusable_parts_searched, std::vector<int>{mannequin}) << seed;
  }
  EXPECT_GE(named, 6);
  EXPECT_GE(searched, 4);
}

// A winner whose listed parts were left unsearched (here none is searched) is named only when
// the scene shows confusable.min_seen_fraction of its matched view: asked for all of it, the
// cow scans that show less of it are rejected as ambiguous, counting the parts left unsearched,
// and those that show all of it are still named; without a list the same scans are named.
TEST_F(RecognizerOnRegressionBase, AWinnerWithListedPartsLeftUnsearchedMustShowItsView) {
  const CowListingMannequin listing = cow_listing_mannequin(*base_);
  const int cow = listing.cow, mannequin = listing.mannequin;
  ASSERT_GE(cow, 0);
  ASSERT_GE(mannequin, 0);
  const ModelBase& listed = listing.base;
  ModelBase unlisted = listed;
  unlisted.parts[static_cast<std::size_t>(cow)].confusable_parts.clear();
  RecognitionParameters whole_view;
  whole_view.confusable.searched_parts = 0;
  whole_view.confusable.min_seen_fraction = 1;
  RecognitionParameters any_view = whole_view;
  any_view.confusable.min_seen_fraction = 0;
  const Recognizer strict(listed, CosmosParameters{}, whole_view);
  const Recognizer lenient(listed, CosmosParameters{}, any_view);
  const Recognizer without_list(unlisted, CosmosParameters{}, whole_view);
  int rejected = 0, named = 0;
  for (std::uint64_t seed = 401; seed < 409; ++seed) {
    const RangeImage image = scan("cow", seed);
    const RecognitionResult plain = lenient.recognize(image);
    if (plain.part != cow || part_pose_searched(plain, mannequin)) continue;
    EXPECT_EQ(without_list.recognize(image).part, cow) << seed;
    const RecognitionResult result = strict.recognize(image);
    if (plain.seen_fraction < 1) {
      ++rejected;
      EXPECT_EQ(result.part, -1) << seed;
      EXPECT_NE(result.reason.find("parts it may be taken for left unsearched: 1"),
                std::string::npos)
          << result.reason;
    } else {
      ++named;
      EXPECT_EQ(result.part, cow) << seed;
    }
  }
  EXPECT_GE(rejected, 1);
  EXPECT_GE(named, 1);
}

// A winner scoring under min_score is rejected as fitting too loosely, and one scoring at
// least that is named as before: with the bar at the median score of ten scans that a
// recognizer without it names, those below are rejected with that reason and the others are
// named with the same part and score.
TEST_F(RecognizerOnRegressionBase, AWinnerScoringUnderTheMinimumIsRejectedAsFittingLoosely) {
  RecognitionParameters no_bar;
  no_bar.min_score = 0;
  const Recognizer unbarred(*base_, CosmosParameters{}, no_bar);
  std::vector<RangeImage> images;
  std::vector<RecognitionResult> named;
  for (std::uint64_t seed = 501; named.size() < 10 && seed < 540; ++seed) {
    const std::string& name = base_->parts[seed % base_->parts.size()].name;
    RangeImage image = scan(name, seed);
    RecognitionResult result = unbarred.recognize(image);
    if (result.status != RecognitionStatus::kOk) continue;
    images.push_back(std::move(image));
    named.push_back(std::move(result));
  }
  ASSERT_EQ(named.size(), 10u);
  std::vector<double> scores;
  for (const RecognitionResult& result : named) scores.push_back(result.score);
  std::nth_element(scores.begin(), scores.begin() + 5, scores.end());
  RecognitionParameters barred = no_bar;
  barred.min_score = scores[5];
  const Recognizer recognizer(*base_, CosmosParameters{}, barred);
  int rejected = 0, kept = 0;
  for (std::size_t k = 0; k < images.size(); ++k) {
    const RecognitionResult result = recognizer.recognize(images[k]);
    if (named[k].score < barred.min_score) {
      ++rejected;
      EXPECT_EQ(result.status, RecognitionStatus::kRejected) << k;
      EXPECT_EQ(result.part, -1) << k;
      EXPECT_EQ(result.reason.rfind("best candidate fits too loosely: score ", 0), 0u)
          << result.reason;
    } else {
      ++kept;
      EXPECT_EQ(result.status, RecognitionStatus::kOk) << k;
      EXPECT_EQ(result.part, named[k].part) << k;
      EXPECT_DOUBLE_EQ(result.score, named[k].score) << k;
    }
  }
  EXPECT_EQ(rejected, 5);
  EXPECT_EQ(kept, 5);
}

// The head and the holes at 100, 110 and 121 % of their catalog size. A scan of the middle
// holes (seed 44) is explained by no candidate: its best registered candidate, the middle
// head, puts surface where the scene has none. The search over the candidates' parts stopped
// at that size, so the decision registers the head's other sizes from its poses, scaled,
// before it rejects the scene; none of them explains it either, and the scene is rejected
// rather than named.
TEST(RecognizerDecision, WhenNoCandidateQualifiesTheBestOnesOtherSizesAreSearched) {
  const PartCatalog catalog = large_catalog();
  const ModelBase base =
      family_base(catalog, {"head", "head-110", "head-121", "holes", "holes-110", "holes-121"});
  const Recognizer recognizer(base, CosmosParameters{}, RecognitionParameters{});

  const RecognitionResult result = recognizer.recognize(scan_part(catalog.at("holes-110"), 44));
  EXPECT_EQ(result.status, RecognitionStatus::kRejected);
  EXPECT_TRUE(result.reason.starts_with("best candidate's surface is not where the scene is"))
      << result.reason;
  ASSERT_GE(result.best_candidate_part, 0);
  EXPECT_TRUE(
      base.parts[static_cast<std::size_t>(result.best_candidate_part)].name.starts_with("head"));
  for (const char* name : {"head", "head-110", "head-121"}) {
    const auto part = std::find_if(base.parts.begin(), base.parts.end(),
                                   [&](const ModelPart& p) { return p.name == name; });
    EXPECT_TRUE(part_pose_searched(result, static_cast<int>(part - base.parts.begin()))) << name;
  }
}

// Flat-faced parts at three sizes each, and a plate: a view of a few of a bracket's faces is
// explained by a section or a cube that contains them about as well as by the bracket.
class RecognizerOnFlatFamilies : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    catalog_ = std::make_unique<PartCatalog>(large_catalog());
    std::vector<std::string> names;
    for (const char* shape : {"l-bracket-3", "t-section-3", "cube-meshed"})
      for (const char* size : {"", "-110", "-121"}) names.push_back(std::string(shape) + size);
    names.push_back("notched-plate-4");
    base_ = std::make_unique<ModelBase>(family_base(*catalog_, names));
    recognizer_ = std::make_unique<Recognizer>(*base_, CosmosParameters{}, RecognitionParameters{});
  }
  static void TearDownTestSuite() {
    recognizer_.reset();
    base_.reset();
    catalog_.reset();
  }
  static RecognitionResult recognize(std::uint64_t seed) {
    const ModelPart& part = base_->parts[seed % base_->parts.size()];
    return recognizer_->recognize(scan_part(catalog_->at(part.name), seed));
  }
  // The best score of `part`'s qualified candidates (-1 when it has none).
  static double best_qualified_score(const RecognitionResult& result, int part) {
    double best = -1;
    for (const RecognitionCandidate& candidate : result.candidates)
      if (candidate.part == part && candidate.qualified) best = std::max(best, candidate.score);
    return best;
  }
  static inline std::unique_ptr<PartCatalog> catalog_;
  static inline std::unique_ptr<ModelBase> base_;
  static inline std::unique_ptr<Recognizer> recognizer_;
};

// When the runner-up is another size of the winner's shape, the best qualified part of another
// shape is compared with the winner too: one scoring within examined_score_margin of every
// candidate of the winner's part has been examined where the two differ.
TEST_F(RecognizerOnFlatFamilies, ARivalOfAnotherSizeDoesNotHideAPartOfAnotherShape) {
  const PartAmbiguityParameters ambiguity;
  int other_shapes = 0, examined = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const RecognitionResult result = recognize(seed);
    if (result.other_shape_part < 0) continue;
    ++other_shapes;
    ASSERT_GE(result.runner_up_part, 0) << seed;
    EXPECT_NE(result.other_shape_part, result.runner_up_part) << seed;
    if (result.status != RecognitionStatus::kOk) continue;
    const double other = best_qualified_score(result, result.other_shape_part);
    if (best_qualified_score(result, result.part) - other >= ambiguity.examined_score_margin - 1e-3)
      continue;
    ++examined;
    EXPECT_TRUE(result.ambiguity_examined) << seed;
  }
  EXPECT_GE(other_shapes, 5);
  EXPECT_GE(examined, 1);
}

// A part is named only when its score and its fit both ways name it: among the parts of other
// shapes (each by its best-scored qualified candidate) none fits the scene better both ways
// beyond the fit's noise, and none scoring higher comes within two_way_fit_margin of its fit;
// each other size of its shape it outfits by the noise at least.
TEST_F(RecognizerOnFlatFamilies, ANamedPartIsTheOneItsScoreAndItsFitBothWaysName) {
  const PartAmbiguityParameters ambiguity;
  int named = 0;
  for (std::uint64_t seed = 41; seed <= 60; ++seed) {
    const RecognitionResult result = recognize(seed);
    if (result.status != RecognitionStatus::kOk) continue;
    ++named;
    const RecognitionCandidate* winner = nullptr;
    for (const RecognitionCandidate& candidate : result.candidates)
      if (candidate.qualified && candidate.part == result.part && candidate.view == result.view &&
          (!winner || candidate.score > winner->score))
        winner = &candidate;
    ASSERT_NE(winner, nullptr) << seed;
    const ModelPart& named_part = base_->parts[static_cast<std::size_t>(result.part)];
    for (const RecognitionCandidate& other : result.candidates) {
      if (!other.qualified || other.part == result.part ||
          other.score < best_qualified_score(result, other.part))
        continue;
      const double lead = two_way_fit(*winner) - two_way_fit(other);
      if (base_->parts[static_cast<std::size_t>(other.part)].mesh == named_part.mesh)
        EXPECT_GE(lead, ambiguity.two_way_fit_noise) << seed;
      else if (other.score > winner->score)
        EXPECT_GT(lead, ambiguity.two_way_fit_margin) << seed;
      else
        EXPECT_GE(lead, -ambiguity.two_way_fit_noise) << seed;
    }
  }
  EXPECT_GE(named, 15);
}

// The other sizes of the winner's shape are registered from its poses, scaled: each has a
// candidate so registered and none searched over its views by the decision. No scan is named
// wrongly that a search over every size's views names rightly; a scaled pose may fit another
// size better than that search did, and leave a scan ambiguous between the two.
TEST_F(RecognizerOnFlatFamilies, TheOtherSizesAreRegisteredFromTheWinnersPosesScaled) {
  RecognitionParameters searching_sizes;
  searching_sizes.size_variants.from_winner_poses = false;
  const Recognizer searching(*base_, CosmosParameters{}, searching_sizes);
  int scaled = 0, named = 0, named_searching = 0, wrong = 0, wrong_searching = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const ModelPart& truth = base_->parts[seed % base_->parts.size()];
    const RangeImage image = scan_part(catalog_->at(truth.name), seed);
    const RecognitionResult result = recognizer_->recognize(image);
    const int truth_index = static_cast<int>(seed % base_->parts.size());
    named += result.part == truth_index ? 1 : 0;
    const RecognitionResult other = searching.recognize(image);
    named_searching += other.part == truth_index ? 1 : 0;
    wrong += result.part >= 0 && result.part != truth_index ? 1 : 0;
    wrong_searching += other.part >= 0 && other.part != truth_index ? 1 : 0;
    for (const RecognitionCandidate& candidate : result.candidates) {
      if (!candidate.from_scaled_size) continue;
      ++scaled;
      EXPECT_FALSE(candidate.from_pose_search) << seed;
      EXPECT_TRUE(base_->parts[static_cast<std::size_t>(candidate.part)].mesh ==
                  base_->parts[static_cast<std::size_t>(result.best_candidate_part)].mesh)
          << seed;
      EXPECT_EQ(std::count_if(result.candidates.begin(), result.candidates.end(),
                              [&](const RecognitionCandidate& c) {
                                return c.part == candidate.part && c.searched_over_views();
                              }),
                1)
          << seed;
    }
  }
  EXPECT_GE(scaled, 12);
  EXPECT_LE(wrong, wrong_searching);
  EXPECT_GE(named, named_searching - 1);
  EXPECT_GE(named, 9);
}

}  // namespace
}  // namespace cosmos
