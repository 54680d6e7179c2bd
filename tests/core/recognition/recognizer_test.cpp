// The recognizer (ch. 5-6) against the regression model base (5 parts x 80 views,
// tests/regression_model_base.hpp): simulated random-pose scans of catalog parts, whose ground
// truth is known, are identified with their pose; a part the base does not hold is rejected,
// and so is a scan without data.
#include "core/recognition/recognizer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/io/model_base_file.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_pose.hpp"
#include "sim/part_scan.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

class RecognizerOnRegressionBase : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    base_ = std::make_unique<ModelBase>(read_model_base(testing::regression_model_base()));
    // The full catalog holds the base's five parts and the bunny, which the base lacks.
    catalog_ = std::make_unique<PartCatalog>(
        read_part_catalog(std::filesystem::path(COSMOS_SOURCE_DIR) / "config/parts.yaml"));
    recognizer_ = std::make_unique<Recognizer>(*base_, CosmosParameters{}, RecognitionParameters{});
  }
  static void TearDownTestSuite() {
    recognizer_.reset();
    catalog_.reset();
    base_.reset();
  }

  // A scan of `name` in the random pose of `seed`, with noise seeded by it too.
  static TriangleMesh mesh_of(const std::string& name) {
    const PartEntry& entry = catalog_->at(name);
    return load_mesh(entry.mesh_path, entry.size_mm);
  }
  static RangeImage scan(const std::string& name, std::uint64_t seed) {
    const TriangleMesh mesh = mesh_of(name);
    ScannerParameters scanner;
    scanner.seed = seed;
    return scan_single_part(mesh, name, random_rotation(seed), scanner, ConditioningParameters{});
  }
  static RangeImage far_half_cut(const std::string& name, std::uint64_t seed);

  static double degrees(double radians) { return radians * 180 / std::numbers::pi; }

  // ADD-S (mean distance from each model point in the true pose to the nearest model point in
  // the estimated one) over about 1,000 of the mesh's vertices, by brute force: a pose that
  // turns a part of revolution about its axis scores 0 here, as it fits the scan as well.
  static double add_s_mm(const TriangleMesh& mesh, const GroundTruthPose& truth,
                         const RigidTransform& estimate) {
    const std::size_t step = std::max<std::size_t>(1, mesh.vertices.size() / 1000);
    std::vector<Eigen::Vector3d> in_truth, in_estimate;
    for (std::size_t i = 0; i < mesh.vertices.size(); i += step) {
      const Eigen::Vector3d p = mesh.vertices[i].cast<double>();
      in_truth.push_back(truth.rotation * p + truth.translation_mm);
      in_estimate.push_back(estimate.apply(p));
    }
    double sum_mm = 0;
    for (const Eigen::Vector3d& p : in_truth) {
      double nearest_mm2 = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& q : in_estimate)
        nearest_mm2 = std::min(nearest_mm2, (p - q).squaredNorm());
      sum_mm += std::sqrt(nearest_mm2);
    }
    return sum_mm / static_cast<double>(in_truth.size());
  }

  static inline std::unique_ptr<ModelBase> base_;
  static inline std::unique_ptr<PartCatalog> catalog_;
  static inline std::unique_ptr<Recognizer> recognizer_;
};

TEST_F(RecognizerOnRegressionBase, IdentifiesScansOfEachPartInTheirTruePose) {
  ASSERT_EQ(base_->parts.size(), 5u);
  for (std::uint64_t seed = 31; seed < 36; ++seed) {
    const int part = static_cast<int>(seed % 5);
    const std::string& name = base_->parts[static_cast<std::size_t>(part)].name;
    const RangeImage image = scan(name, seed);
    ASSERT_TRUE(image.ground_truth.has_value());
    const TriangleMesh mesh = mesh_of(name);
    const RecognitionResult result = recognizer_->recognize(image);
    const GroundTruthPose& truth = *image.ground_truth;
    const double rotation_error_deg =
        degrees(rotation_angle_between_rad(result.T_scanner_part.rotation, truth.rotation));
    const double translation_error_mm =
        (result.T_scanner_part.translation_mm - truth.translation_mm).norm();
    const double add_s = add_s_mm(mesh, truth, result.T_scanner_part);
    std::printf(
        "seed %d %s: %s, part %d, score %.3f, inliers %.3f, rms %.3f mm, %.2f deg, %.2f mm, "
        "ADD-S %.3f mm\n",
        static_cast<int>(seed), name.c_str(), to_string(result.status), result.part, result.score,
        result.inlier_fraction, result.registration_rms_mm, rotation_error_deg,
        translation_error_mm, add_s);
    ASSERT_EQ(result.status, RecognitionStatus::kOk) << name << ": " << result.reason;
    EXPECT_TRUE(result.reason.empty());
    EXPECT_EQ(result.part, part) << name;
    ASSERT_GE(result.view, 0);
    EXPECT_EQ(base_->views[static_cast<std::size_t>(result.view)].part_index, result.part);
    // The decision's thresholds hold for the winner.
    EXPECT_GE(result.inlier_fraction, RecognitionParameters{}.min_inlier_fraction);
    EXPECT_LE(result.registration_rms_mm, RecognitionParameters{}.max_rms_mm);
    // The evaluation's criterion (ADD-S below a tenth of the diameter) for every part, and
    // the pose itself for all but the coupling: its scan of seed 34 registers 47 degrees off
    // the truth with 96 % support at 0.03 mm RMS (the truth: 94 % at 0.01 mm), ADD-S 3.7 mm.
    const double diameter_mm = base_->parts[static_cast<std::size_t>(part)].diameter_mm;
    EXPECT_LT(add_s, 0.1 * diameter_mm) << name;
    if (name != "couplingdown") {
      EXPECT_LT(add_s, 0.05) << name;
      EXPECT_LT(rotation_error_deg, 0.5) << name;
      EXPECT_LT(translation_error_mm, 0.5) << name;
    }
    EXPECT_GT(result.scene_points, RecognitionParameters{}.min_scene_points);
    EXPECT_GE(result.views_examined, 1);
  }
}

// The pose the recognizer reports is its best candidate's registration composed with that
// view's scan pose; and the same scan gives the same answer again (every budget is counted).
TEST_F(RecognizerOnRegressionBase, ReportsItsBestCandidatesPoseAndRepeatsItself) {
  const RangeImage image = scan(base_->parts[1].name, 41);
  const RecognitionResult first = recognizer_->recognize(image);
  ASSERT_EQ(first.status, RecognitionStatus::kOk) << first.reason;
  const RecognitionCandidate* best = nullptr;
  for (const RecognitionCandidate& candidate : first.candidates)
    if (candidate.view == first.view && candidate.registered &&
        (!best || candidate.score > best->score))
      best = &candidate;
  ASSERT_NE(best, nullptr);
  EXPECT_EQ(best->part, first.part);
  EXPECT_DOUBLE_EQ(best->inlier_fraction, first.inlier_fraction);
  const RigidTransform expected = best->T_model_scene.inverse() *
                                  base_->views[static_cast<std::size_t>(first.view)].T_scanner_part;
  EXPECT_LT(rotation_angle_between_rad(expected.rotation, first.T_scanner_part.rotation), 1e-9);
  EXPECT_LT((expected.translation_mm - first.T_scanner_part.translation_mm).norm(), 1e-9);

  const RecognitionResult again = recognizer_->recognize(image);
  EXPECT_EQ(again.part, first.part);
  EXPECT_EQ(again.view, first.view);
  EXPECT_EQ(again.score, first.score);
  EXPECT_EQ(again.T_scanner_part.rotation, first.T_scanner_part.rotation);
  EXPECT_EQ(again.candidates.size(), first.candidates.size());
}

// The vote index (core/indexing/) on its own: with the pose search over every part taken
// away (searched_parts 0) and spectral selection cut to its single best view, seeded scans the
// selected view does not explain are still identified in their true pose, from the poses the
// scene's CSMP pairs voted for.
TEST_F(RecognizerOnRegressionBase, TheVoteIndexFindsThePartAndPoseWithoutSearchingEveryPart) {
  RecognitionParameters parameters;
  parameters.vote_index.enabled = true;  // off by default
  parameters.searched_parts = 0;
  parameters.selection.best_clusters = 1;
  parameters.selection.best_views = 1;
  const Recognizer recognizer(*base_, CosmosParameters{}, parameters);
  EXPECT_GT(recognizer.patch_pair_table().size(), 0u);
  int decided_by_votes = 0;
  for (std::uint64_t seed = 61; seed < 81; ++seed) {
    const int part = static_cast<int>(seed % 5);
    const std::string& name = base_->parts[static_cast<std::size_t>(part)].name;
    const RangeImage image = scan(name, seed);
    const RecognitionResult result = recognizer.recognize(image);
    const RecognitionCandidate* winner = nullptr;
    for (const RecognitionCandidate& candidate : result.candidates)
      if (candidate.registered && candidate.part == result.part && candidate.view == result.view &&
          candidate.score == result.score)
        winner = &candidate;
    const bool voted = winner && winner->from_vote_index;
    const double add_s = add_s_mm(mesh_of(name), *image.ground_truth, result.T_scanner_part);
    std::printf("seed %d %s: %s, part %d, %s, ADD-S %.3f mm\n", static_cast<int>(seed),
                name.c_str(), to_string(result.status), result.part, voted ? "voted" : "selected",
                add_s);
    if (!voted) continue;
    ++decided_by_votes;
    ASSERT_EQ(result.status, RecognitionStatus::kOk) << name << ": " << result.reason;
    EXPECT_EQ(result.part, part) << name;
    const double diameter_mm = base_->parts[static_cast<std::size_t>(part)].diameter_mm;
    // The evaluation's criterion for every part, ADD-S@2% for all but the coupling, which also
    // registers off its true pose from selected views (the test above).
    EXPECT_LT(add_s, 0.1 * diameter_mm) << name;
    if (name != "couplingdown") {
      EXPECT_LT(add_s, 0.02 * diameter_mm) << name;
    }
  }
  EXPECT_GE(decided_by_votes, 3);
}

// Scans of parts lying in their stable poses (sim/part_pose.hpp), in a cell told they do: the
// resting-pose search finds what the selected views do not, the pose search over every part
// is not needed, and a part lifted off the belt is refused rather than recognized floating.
TEST_F(RecognizerOnRegressionBase, PartsAtRestAreFoundInTheirRestingPosesAndFloatingOnesRefused) {
  RecognitionParameters parameters;
  parameters.resting.parts_rest = true;
  const Recognizer recognizer(*base_, CosmosParameters{}, parameters);
  for (const ModelPart& part : base_->parts) {
    ASSERT_FALSE(part.resting_poses.empty()) << part.name;
    ASSERT_GE(part.hull_vertices_mm.size(), 4u) << part.name;
  }
  int found_resting = 0;
  int covered_scans = 0;
  for (std::uint64_t seed = 91; seed < 111; ++seed) {
    const int part = static_cast<int>(seed % 5);
    const std::string& name = base_->parts[static_cast<std::size_t>(part)].name;
    const TriangleMesh mesh = mesh_of(name);
    ScannerParameters scanner;
    scanner.seed = seed;
    RangeImage image = scan_single_part(mesh, name, resting_rotation(mesh, seed), scanner,
                                        ConditioningParameters{});
    const RecognitionResult result = recognizer.recognize(image);
    ASSERT_EQ(result.status, RecognitionStatus::kOk)
        << name << " seed " << seed << ": " << result.reason;
    EXPECT_EQ(result.part, part) << name << " seed " << seed;
    // A part whose kept resting poses cover most of the chance is found among them; one that
    // rolls (the coupling: its side is many unlikely hull faces) may need the search over
    // every part.
    if (base_->parts[static_cast<std::size_t>(part)].resting_coverage() >=
        parameters.resting.min_coverage) {
      ++covered_scans;
      EXPECT_FALSE(result.catalog_searched) << name << " seed " << seed;
    }
    const double diameter_mm = base_->parts[static_cast<std::size_t>(part)].diameter_mm;
    EXPECT_LT(add_s_mm(mesh, *image.ground_truth, result.T_scanner_part), 0.02 * diameter_mm)
        << name << " seed " << seed;
    for (const RecognitionCandidate& candidate : result.candidates)
      found_resting += candidate.from_resting_search && candidate.part == result.part &&
                       candidate.view == result.view && candidate.score == result.score;
    if (seed % 4 != 0) continue;
    // The same surface 6 mm higher: the part would float above the belt.
    for (float& z_mm : image.z_mm.values()) z_mm += 6.0f;
    const RecognitionResult floating = recognizer.recognize(image);
    EXPECT_EQ(floating.status, RecognitionStatus::kRejected) << name << " seed " << seed;
    EXPECT_EQ(floating.part, -1) << name;
  }
  EXPECT_GE(found_resting, 1);
  EXPECT_GE(covered_scans, 12);
}

// Parts in random poses still lie on the belt, their lowest point on it: told so, the
// recognizer takes the same scans, and refuses each one lifted off the belt, with the reason.
TEST_F(RecognizerOnRegressionBase, APartLiftedOffTheBeltIsRefusedWhenPartsLieOnIt) {
  RecognitionParameters parameters;
  parameters.resting.parts_touch_belt = true;
  const Recognizer recognizer(*base_, CosmosParameters{}, parameters);
  for (std::uint64_t seed = 121; seed < 126; ++seed) {
    const int part = static_cast<int>(seed % 5);
    const std::string& name = base_->parts[static_cast<std::size_t>(part)].name;
    RangeImage image = scan(name, seed);
    const RecognitionResult lying = recognizer.recognize(image);
    ASSERT_EQ(lying.status, RecognitionStatus::kOk) << name << ": " << lying.reason;
    EXPECT_EQ(lying.part, part) << name;
    for (float& z_mm : image.z_mm.values()) z_mm += 6.0f;
    const RecognitionResult lifted = recognizer.recognize(image);
    EXPECT_EQ(lifted.status, RecognitionStatus::kRejected) << name;
    EXPECT_NE(lifted.reason.find("does not touch the belt"), std::string::npos)
        << name << ": " << lifted.reason;
  }
}

// A regression scan whose far half is replaced by measured belt: a scene that shows only
// part of most views, the rest of them where the scanner saw the belt.
RangeImage RecognizerOnRegressionBase::far_half_cut(const std::string& name, std::uint64_t seed) {
  RangeImage image = scan(name, seed);
  EXPECT_TRUE(image.belt_known()) << name;
  int first_row = image.height(), last_row = -1;
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column)
      if (!std::isnan(image.z_mm(column, row))) {
        first_row = std::min(first_row, row);
        last_row = std::max(last_row, row);
      }
  EXPECT_LT(first_row, last_row) << name;
  for (int row = (first_row + last_row) / 2; row <= last_row; ++row)
    for (int column = 0; column < image.width(); ++column) {
      image.z_mm(column, row) = std::numeric_limits<float>::quiet_NaN();
      image.belt_seen(column, row) = 1;
    }
  return image;
}

// Whether the result's winner came from the search over every part with less than
// min_accepted_seen_fraction of its view seen.
bool accepted_with_view_contradicted(const RecognitionResult& result) {
  const auto winner = std::find_if(result.candidates.begin(), result.candidates.end(),
                                   [&](const RecognitionCandidate& c) {
                                     return c.part == result.part && c.view == result.view;
                                   });
  return result.status == RecognitionStatus::kOk &&
         result.seen_fraction < RecognitionParameters{}.min_accepted_seen_fraction &&
         winner != result.candidates.end() && winner->from_pose_search;
}

// On the cut scans, winners from the search over every part that a lenient recognizer accepts
// with less than min_accepted_seen_fraction of their view seen are refused. (The free-space
// rule, which drops most such poses before they are registered, is off in both.)
TEST_F(RecognizerOnRegressionBase, AWinnerWhoseViewTheSceneContradictsIsRejected) {
  RecognitionParameters strict_parameters;
  strict_parameters.max_fraction_over_belt = 1;
  RecognitionParameters lenient_parameters = strict_parameters;
  lenient_parameters.min_accepted_seen_fraction = lenient_parameters.min_seen_fraction;
  const Recognizer lenient(*base_, CosmosParameters{}, lenient_parameters);
  const Recognizer strict(*base_, CosmosParameters{}, strict_parameters);
  int refused = 0;
  for (std::uint64_t seed = 131; seed < 141; ++seed) {
    const std::string& name = base_->parts[static_cast<std::size_t>(seed % 5)].name;
    const RangeImage image = far_half_cut(name, seed);
    const RecognitionResult accepted = lenient.recognize(image);
    if (!accepted_with_view_contradicted(accepted)) continue;
    const RecognitionResult judged = strict.recognize(image);
    EXPECT_EQ(judged.status, RecognitionStatus::kRejected) << name << " seed " << seed;
    EXPECT_NE(judged.reason.find("of the best candidate's surface is where the scene is"),
              std::string::npos)
        << name << " seed " << seed << ": " << judged.reason;
    ++refused;
  }
  EXPECT_GE(refused, 2);
}

// The free-space rule (free_space.hpp): the search's field poses that place their part over
// the measured belt are dropped before they are ranked or registered, so the same lenient
// recognizer accepts no winner whose view the cut scene contradicts, where without the rule
// it accepts at least two.
TEST_F(RecognizerOnRegressionBase, SearchedPosesOverTheMeasuredBeltAreDropped) {
  RecognitionParameters lenient_parameters;
  lenient_parameters.min_accepted_seen_fraction = lenient_parameters.min_seen_fraction;
  RecognitionParameters without_rule = lenient_parameters;
  without_rule.max_fraction_over_belt = 1;
  const Recognizer with(*base_, CosmosParameters{}, lenient_parameters);
  const Recognizer without(*base_, CosmosParameters{}, without_rule);
  int contradicted_with = 0, contradicted_without = 0;
  for (std::uint64_t seed = 131; seed < 141; ++seed) {
    const std::string& name = base_->parts[static_cast<std::size_t>(seed % 5)].name;
    const RangeImage image = far_half_cut(name, seed);
    contradicted_with += accepted_with_view_contradicted(with.recognize(image)) ? 1 : 0;
    contradicted_without += accepted_with_view_contradicted(without.recognize(image)) ? 1 : 0;
  }
  EXPECT_GE(contradicted_without, 2);
  EXPECT_EQ(contradicted_with, 0);
}

TEST_F(RecognizerOnRegressionBase, RejectsAPartTheBaseDoesNotHold) {
  for (const ModelPart& part : base_->parts) ASSERT_NE(part.name, "bunny");
  for (std::uint64_t seed : {51, 52}) {
    const RecognitionResult result = recognizer_->recognize(scan("bunny", seed));
    std::printf("bunny seed %d: %s (%s), inliers %.3f, rms %.3f mm\n", static_cast<int>(seed),
                to_string(result.status), result.reason.c_str(), result.inlier_fraction,
                result.registration_rms_mm);
    EXPECT_EQ(result.status, RecognitionStatus::kRejected) << "taken for part " << result.part;
    EXPECT_EQ(result.part, -1);
    EXPECT_FALSE(result.reason.empty());
  }
}

// The parts the search over every part registered for a recognition.
int parts_registered_by_search(const RecognitionResult& result) {
  std::vector<int> parts;
  for (const RecognitionCandidate& candidate : result.candidates)
    if (candidate.from_pose_search &&
        std::find(parts.begin(), parts.end(), candidate.part) == parts.end())
      parts.push_back(candidate.part);
  return static_cast<int>(parts.size());
}

TEST_F(RecognizerOnRegressionBase, TheSearchRegistersAtMostItsBudgetOfParts) {
  // The bunny is in no part of the base: nothing explains its scans, so without a budget the
  // search registers every part whose field fits convincingly or ranks among the waiting.
  RecognitionParameters unbounded;
  unbounded.registered_parts = 100;
  RecognitionParameters bounded;
  bounded.registered_parts = 2;
  const Recognizer all(*base_, CosmosParameters{}, unbounded);
  const Recognizer budget(*base_, CosmosParameters{}, bounded);
  int most_registered = 0;
  for (std::uint64_t seed : {51, 52, 53}) {
    const RangeImage image = scan("bunny", seed);
    const RecognitionResult without = all.recognize(image);
    const RecognitionResult with = budget.recognize(image);
    most_registered = std::max(most_registered, parts_registered_by_search(without));
    EXPECT_LE(parts_registered_by_search(with), 2) << seed;
    EXPECT_EQ(with.status, RecognitionStatus::kRejected) << seed;
  }
  EXPECT_GT(most_registered, 2);
}

// A candidate from the §5.2 selection (not from a search nor the vote index).
bool from_selected_view(const RecognitionCandidate& candidate) {
  return !candidate.from_pose_search && !candidate.from_resting_search &&
         !candidate.from_vote_index;
}

TEST_F(RecognizerOnRegressionBase, SelectedViewsBeyondTheFirstFewWaitForTheSearches) {
  const RecognitionParameters defaults;
  ASSERT_LT(defaults.views_before_search,
            defaults.selection.best_clusters * defaults.selection.best_views);
  RecognitionParameters views_first;
  views_first.views_before_search = 1000;
  const Recognizer all_views_first(*base_, CosmosParameters{}, views_first);
  // Nothing explains the bunny: its first selected views, then the search, then the rest of
  // its selected views, the same views as when all are verified first.
  for (std::uint64_t seed : {51, 52}) {
    const RecognitionResult result = recognizer_->recognize(scan("bunny", seed));
    const RecognitionResult reference = all_views_first.recognize(scan("bunny", seed));
    EXPECT_EQ(result.status, RecognitionStatus::kRejected) << seed;
    std::vector<int> views, reference_views;
    std::string order;
    for (const RecognitionCandidate& c : result.candidates) {
      order += from_selected_view(c) ? 'v' : 's';
      if (from_selected_view(c)) views.push_back(c.view);
    }
    for (const RecognitionCandidate& c : reference.candidates)
      if (from_selected_view(c)) reference_views.push_back(c.view);
    EXPECT_EQ(views, reference_views) << seed;
    const std::size_t first_search = order.find('s');
    ASSERT_NE(first_search, std::string::npos) << seed;
    EXPECT_EQ(first_search, static_cast<std::size_t>(defaults.views_before_search)) << order;
    EXPECT_NE(order.find('v', first_search), std::string::npos) << order;
  }
  // Scans of the base's parts: the order changes what a recognition costs, not its answer;
  // and the scans the search explains have their later selected views verified only as the
  // winner's rival, at most rival_verifications of them.
  int explained_by_search = 0;
  for (std::uint64_t seed = 31; seed < 46; ++seed) {
    const std::string& name = base_->parts[static_cast<std::size_t>(seed % 5)].name;
    const RangeImage image = scan(name, seed);
    const RecognitionResult result = recognizer_->recognize(image);
    const RecognitionResult reference = all_views_first.recognize(image);
    EXPECT_EQ(result.status, reference.status) << name << " seed " << seed;
    EXPECT_EQ(result.part, reference.part) << name << " seed " << seed;
    const auto first_search =
        std::find_if(result.candidates.begin(), result.candidates.end(),
                     [](const RecognitionCandidate& c) { return c.from_pose_search; });
    if (first_search == result.candidates.end() || result.status != RecognitionStatus::kOk)
      continue;
    const bool search_explained =
        std::any_of(first_search, result.candidates.end(), [&](const RecognitionCandidate& c) {
          return c.from_pose_search && c.part == result.part &&
                 c.inlier_fraction >= defaults.sufficient_support;
        });
    if (!search_explained) continue;
    ++explained_by_search;
    const auto later_views =
        std::count_if(first_search, result.candidates.end(), from_selected_view);
    EXPECT_LE(later_views, defaults.ambiguity.rival_verifications) << name << " seed " << seed;
  }
  EXPECT_GE(explained_by_search, 1);
}

TEST_F(RecognizerOnRegressionBase, APartWhoseFirstPoseExplainsLittleHasNoMoreTried) {
  // The free-space rule off in both: it drops many of the poses the rule would abandon.
  RecognitionParameters with_rule;
  with_rule.max_fraction_over_belt = 1;
  RecognitionParameters persistent = with_rule;
  persistent.abandoned_part_support = 0;
  const Recognizer abandoning(*base_, CosmosParameters{}, with_rule);
  const Recognizer every_pose(*base_, CosmosParameters{}, persistent);
  const double abandoned = RecognitionParameters{}.abandoned_part_support;
  int abandoned_parts = 0;
  for (std::uint64_t seed : {51, 52, 53}) {
    const RangeImage image = scan("bunny", seed);
    const RecognitionResult result = abandoning.recognize(image);
    const RecognitionResult reference = every_pose.recognize(image);
    EXPECT_EQ(result.status, RecognitionStatus::kRejected) << seed;
    EXPECT_EQ(reference.status, RecognitionStatus::kRejected) << seed;
    // Per part, the search's poses in the order it registered them.
    for (int index = 0; index < static_cast<int>(base_->parts.size()); ++index) {
      const std::string& name = base_->parts[static_cast<std::size_t>(index)].name;
      std::vector<const RecognitionCandidate*> poses, reference_poses;
      for (const RecognitionCandidate& c : result.candidates)
        if (c.from_pose_search && c.part == index) poses.push_back(&c);
      for (const RecognitionCandidate& c : reference.candidates)
        if (c.from_pose_search && c.part == index) reference_poses.push_back(&c);
      if (poses.empty()) continue;
      // A part is never searched further than without the rule, and one stopped after its
      // first pose had that pose registered, explaining less than the rule's support.
      EXPECT_LE(poses.size(), reference_poses.size()) << name << " seed " << seed;
      if (poses.size() == 1 && reference_poses.size() > 1) {
        EXPECT_TRUE(poses.front()->registered) << name;
        EXPECT_LT(poses.front()->inlier_fraction, abandoned) << name;
        ++abandoned_parts;
      }
    }
  }
  EXPECT_GE(abandoned_parts, 2);
}

TEST_F(RecognizerOnRegressionBase, AScanWithoutDataIsRejectedWithItsReason) {
  const RecognitionResult empty = recognizer_->recognize(RangeImage{});
  EXPECT_EQ(empty.status, RecognitionStatus::kRejected);
  EXPECT_EQ(empty.reason, "empty scan: no range data");
  RangeImage blank(40, 30, 0.4, 0.4);
  for (float& z : blank.z_mm.values()) z = std::numeric_limits<float>::quiet_NaN();
  const RecognitionResult nothing = recognizer_->recognize(blank);
  EXPECT_EQ(nothing.status, RecognitionStatus::kRejected);
  EXPECT_EQ(nothing.reason, "empty scan: no range data");
  EXPECT_EQ(nothing.part, -1);
  EXPECT_STREQ(to_string(RecognitionStatus::kOk), "ok");
  EXPECT_STREQ(to_string(RecognitionStatus::kRejected), "rejected");
}

}  // namespace
}  // namespace cosmos
