// The pose search (the recognizer's fallback, part_pose_search.hpp) on simulated random-pose
// scans of the regression catalog's parts, whose ground truth is known: on its own part it
// lands where registration converges to the true pose, without any start from spectral
// selection, and another part fits the scan worse.
#include "core/recognition/part_pose_search.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <numbers>

#include "core/io/model_base_file.hpp"
#include "core/modelbase/model_surface.hpp"
#include "core/recognition/free_space.hpp"
#include "core/recognition/pose_hypotheses.hpp"
#include "core/recognition/recognizer.hpp"
#include "core/representation/cosmos_pipeline.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_pose.hpp"
#include "sim/part_scan.hpp"
#include "tests/core/backwards_task_runner.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

class PartPoseSearch : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    base_ = std::make_unique<ModelBase>(read_model_base(testing::regression_model_base()));
    catalog_ = std::make_unique<PartCatalog>(read_part_catalog(
        std::filesystem::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml"));
  }
  static void TearDownTestSuite() {
    catalog_.reset();
    base_.reset();
  }

  struct Scan {
    RangeImage image;
    RegistrationPoints points;
  };
  static Scan scan(int part, std::uint64_t seed) {
    const std::string& name = base_->parts[static_cast<std::size_t>(part)].name;
    const PartEntry& entry = catalog_->at(name);
    const TriangleMesh mesh = load_mesh(entry.mesh_path, entry.size_mm);
    Scan result;
    result.image = scan_single_part(mesh, name, random_rotation(seed), ScannerParameters{},
                                    ConditioningParameters{});
    const ViewAnalysis analysis = analyze_view(result.image, CosmosParameters{});
    RegistrationPointParameters points = RecognitionParameters{}.scene_points;
    points.stride_px = 2;
    result.points = build_registration_points(result.image, points, &analysis.frames).points;
    return result;
  }

  static std::vector<PartSearchModel> search_models() {
    std::vector<PartSearchModel> models;
    for (int part = 0; part < static_cast<int>(base_->parts.size()); ++part)
      models.push_back(build_part_search_model(*base_, part));
    return models;
  }

  static inline std::unique_ptr<ModelBase> base_;
  static inline std::unique_ptr<PartCatalog> catalog_;
};

TEST_F(PartPoseSearch, FindsTheTruePoseOfRandomPoseScansAndOtherPartsFitWorse) {
  const RecognitionParameters parameters;
  const int parts = static_cast<int>(base_->parts.size());
  ASSERT_EQ(parts, 5);
  const std::vector<PartSearchModel> models = search_models();
  ModelSurfaces surfaces(*base_, ModelSurfaceCacheParameters{});
  for (std::uint64_t seed = 101; seed < 111; ++seed) {
    const int part = static_cast<int>(seed % parts);
    const Scan scene = scan(part, seed);
    ASSERT_GT(scene.points.size(), 100) << seed;
    const std::vector<ViewPoseHypothesis> found =
        search_part_pose(scene.points, *base_, models[static_cast<std::size_t>(part)],
                         parameters.registration, parameters.search, surfaces);
    ASSERT_FALSE(found.empty()) << seed;
    const GroundTruthPose& truth = *scene.image.ground_truth;
    const RigidTransform T_part_scene_true =
        RigidTransform{truth.rotation, truth.translation_mm}.inverse();
    // Some returned pose lies within what registration (ch. 6) converges from, and registered
    // from there its view fits the scene as well as at the true pose (which is what the
    // recognizer keeps). The coupling is nearly a surface of revolution: its poses turned a
    // few degrees about the axis fit almost alike.
    double nearest_deg = 180, best_fit_ratio = 1e9;
    for (const ViewPoseHypothesis& hypothesis : found) {
      const ModelBaseView& view = base_->views[static_cast<std::size_t>(hypothesis.view)];
      EXPECT_EQ(view.part_index, part);
      const RigidTransform T_scanner_part =
          hypothesis.T_model_scene.inverse() * view.T_scanner_part;
      nearest_deg = std::min(
          nearest_deg, rotation_angle_between_rad(T_scanner_part.rotation, truth.rotation) * 180 /
                           std::numbers::pi);
      const ModelSurface model(view);
      const RegistrationResult registered = register_views(
          scene.points, model.points(), hypothesis.T_model_scene, parameters.registration);
      const double fit_mm2 = score_alignment(scene.points, model.points(), registered.T_model_scene,
                                             parameters.registration)
                                 .truncated_mean_square_mm2;
      const double true_fit_mm2 =
          score_alignment(scene.points, model.points(), view.T_scanner_part * T_part_scene_true,
                          parameters.registration)
              .truncated_mean_square_mm2;
      best_fit_ratio = std::min(best_fit_ratio, fit_mm2 / (true_fit_mm2 + 1e-3));
    }
    EXPECT_LT(nearest_deg, 12.0) << "seed " << seed << ", " << truth.part;
    EXPECT_LT(best_fit_ratio, 1.05) << "seed " << seed << ", " << truth.part;
    const int other = (part + 1) % parts;
    const std::vector<ViewPoseHypothesis> elsewhere =
        search_part_pose(scene.points, *base_, models[static_cast<std::size_t>(other)],
                         parameters.registration, parameters.search, surfaces);
    // Another part fits worse, or so badly that no pose passes the gate at all.
    if (elsewhere.empty()) continue;
    EXPECT_GT(elsewhere[0].truncated_mean_square_mm2, 2 * found[0].truncated_mean_square_mm2)
        << "seed " << seed << ", " << truth.part << " against "
        << base_->parts[static_cast<std::size_t>(other)].name;
  }
}

// What the recognizer ranks the searched parts by: the field stages alone put the scan's own
// part first, with a fit convincing enough to register it at once, and the other parts so
// many times worse that they are not registered.
TEST_F(PartPoseSearch, FieldStagesAloneTellTheScansPartFromTheOthers) {
  const RecognitionParameters parameters;
  const int parts = static_cast<int>(base_->parts.size());
  const std::vector<PartSearchModel> models = search_models();
  int ranked_first = 0, convincing = 0, others_hopeless = 0;
  for (std::uint64_t seed = 101; seed < 111; ++seed) {
    const int part = static_cast<int>(seed % parts);
    const Scan scene = scan(part, seed);
    std::vector<double> best_fit_mm2;
    for (int candidate = 0; candidate < parts; ++candidate) {
      const std::vector<FieldHypothesis> poses = field_pose_hypotheses(
          scene.points, *base_, models[static_cast<std::size_t>(candidate)], parameters.search);
      ASSERT_FALSE(poses.empty()) << seed;
      ASSERT_LE(poses.size(), static_cast<std::size_t>(parameters.search.refined_hypotheses));
      for (std::size_t k = 1; k < poses.size(); ++k)
        EXPECT_LE(poses[k - 1].truncated_mean_square_mm2, poses[k].truncated_mean_square_mm2);
      best_fit_mm2.push_back(poses.front().truncated_mean_square_mm2);
    }
    const double own = best_fit_mm2[static_cast<std::size_t>(part)];
    double best_other = 1e9;
    for (int other = 0; other < parts; ++other)
      if (other != part)
        best_other = std::min(best_other, best_fit_mm2[static_cast<std::size_t>(other)]);
    ranked_first += own < best_other;
    convincing += own <= parameters.convincing_field_fit_mm2;
    others_hopeless += best_other > parameters.search.worst_kept_score_mm2(own);
  }
  // Measured: own 0.06-0.16 mm^2, the best other part 2.1-30 mm^2.
  EXPECT_EQ(ranked_first, 10);
  EXPECT_EQ(convincing, 10);
  EXPECT_EQ(others_hopeless, 10);
}

// The field stages align and score their hypotheses in shares; threads that end in any order
// (a backwards runner) give the same poses, scores and order to the bit, the first stage's
// abandoned starts included.
TEST_F(PartPoseSearch, FieldStagesInSharesGiveTheSamePoses) {
  const RecognitionParameters parameters;
  const int parts = static_cast<int>(base_->parts.size());
  const std::vector<PartSearchModel> models = search_models();
  const BackwardsTaskRunner backwards;
  for (std::uint64_t seed = 101; seed < 104; ++seed) {
    const Scan scene = scan(static_cast<int>(seed % parts), seed);
    for (int candidate = 0; candidate < parts; ++candidate) {
      const PartSearchModel& model = models[static_cast<std::size_t>(candidate)];
      const std::vector<FieldHypothesis> alone =
          field_pose_hypotheses(scene.points, *base_, model, parameters.search);
      const std::vector<FieldHypothesis> shared =
          field_pose_hypotheses(scene.points, *base_, model, parameters.search, backwards);
      ASSERT_EQ(alone.size(), shared.size()) << seed << " " << candidate;
      for (std::size_t k = 0; k < alone.size(); ++k) {
        EXPECT_EQ(alone[k].truncated_mean_square_mm2, shared[k].truncated_mean_square_mm2);
        EXPECT_EQ(alone[k].T_part_scene.rotation, shared[k].T_part_scene.rotation);
        EXPECT_EQ(alone[k].T_part_scene.translation_mm, shared[k].T_part_scene.translation_mm);
      }
    }
  }
  // Every stage of every search went to the runner in two shares.
  EXPECT_EQ(backwards.batches, 3 * parts * 3);
  EXPECT_EQ(backwards.tasks, 2 * backwards.batches);
}

// The search's registrations on the views nearest the field poses run in shares too: the same
// views, poses and scores to the bit, and they read the surfaces the views were unpacked into.
TEST_F(PartPoseSearch, RegistrationsInSharesGiveTheSamePoses) {
  const RecognitionParameters parameters;
  const int parts = static_cast<int>(base_->parts.size());
  const std::vector<PartSearchModel> models = search_models();
  const BackwardsTaskRunner backwards;
  int registered = 0;
  for (std::uint64_t seed = 104; seed < 107; ++seed) {
    const int part = static_cast<int>(seed % parts);
    const Scan scene = scan(part, seed);
    const PartSearchModel& model = models[static_cast<std::size_t>(part)];
    const std::vector<FieldHypothesis> poses =
        field_pose_hypotheses(scene.points, *base_, model, parameters.search);
    ModelSurfaces alone_surfaces(*base_, parameters.surfaces),
        shared_surfaces(*base_, parameters.surfaces);
    const std::vector<ViewPoseHypothesis> alone =
        register_field_hypotheses(scene.points, *base_, model, poses, parameters.registration,
                                  parameters.search, alone_surfaces);
    const std::vector<ViewPoseHypothesis> shared =
        register_field_hypotheses(scene.points, *base_, model, poses, parameters.registration,
                                  parameters.search, shared_surfaces, backwards);
    ASSERT_EQ(alone.size(), shared.size()) << seed;
    for (std::size_t k = 0; k < alone.size(); ++k) {
      EXPECT_EQ(alone[k].view, shared[k].view) << seed;
      EXPECT_EQ(alone[k].truncated_mean_square_mm2, shared[k].truncated_mean_square_mm2);
      EXPECT_EQ(alone[k].T_model_scene.rotation, shared[k].T_model_scene.rotation);
      EXPECT_EQ(alone[k].T_model_scene.translation_mm, shared[k].T_model_scene.translation_mm);
    }
    EXPECT_EQ(alone_surfaces.unpackings(), shared_surfaces.unpackings()) << seed;
    registered += alone.empty() ? 0 : 1;
  }
  EXPECT_EQ(registered, 3);
  // The gate and the registrations, each batch in two shares.
  EXPECT_EQ(backwards.batches, 2 * 3);
  EXPECT_EQ(backwards.tasks, 2 * backwards.batches);
}

// The quick stage (CatalogRankParameters) orders the search over every part: on the same
// scans it puts the scan's own part first or second, its poses best first and no more than it
// aligns. The regression base has a quarter of the cell's views, so its start views lie twice
// as far apart and the quick stage's few alignment steps reach the true pose less often than
// on the cell's base; a scan whose part ranks second costs one more part's search, not its
// identification.
TEST_F(PartPoseSearch, QuickFitPutsTheScansOwnPartFirst) {
  const RecognitionParameters parameters;
  const int parts = static_cast<int>(base_->parts.size());
  const std::vector<PartSearchModel> models = search_models();
  int ranked_first = 0, ranked_second = 0;
  for (std::uint64_t seed = 101; seed < 111; ++seed) {
    const int part = static_cast<int>(seed % parts);
    const Scan scene = scan(part, seed);
    std::vector<double> quick_fit_mm2;
    const QuickFitPoints quick_points = quick_fit_points(scene.points, parameters.catalog_rank);
    for (int candidate = 0; candidate < parts; ++candidate) {
      const std::vector<FieldHypothesis> poses =
          quick_field_poses(quick_points, *base_, models[static_cast<std::size_t>(candidate)],
                            parameters.search, parameters.catalog_rank);
      ASSERT_FALSE(poses.empty()) << seed;
      ASSERT_LE(poses.size(), static_cast<std::size_t>(parameters.catalog_rank.aligned));
      for (std::size_t k = 1; k < poses.size(); ++k)
        EXPECT_LE(poses[k - 1].truncated_mean_square_mm2, poses[k].truncated_mean_square_mm2);
      quick_fit_mm2.push_back(poses.front().truncated_mean_square_mm2);
    }
    const double own = quick_fit_mm2[static_cast<std::size_t>(part)];
    int better = 0;
    for (int other = 0; other < parts; ++other)
      better += other != part && quick_fit_mm2[static_cast<std::size_t>(other)] <= own;
    std::printf("seed %d part %d: quick fit %.3f mm^2, %d parts fit better\n",
                static_cast<int>(seed), part, own, better);
    ranked_first += better == 0;
    ranked_second += better <= 1;
  }
  EXPECT_GE(ranked_first, 7);
  EXPECT_GE(ranked_second, 9);
}

// The resting search puts each start's centroid on the scene's from the part's view nearest
// the vertical: every view of the part is there with its centroid, and the pose search's
// starts are its coarse views.
TEST_F(PartPoseSearch, TheSearchModelHoldsEveryViewsCentroid) {
  const RecognitionParameters parameters;
  const PartSearchModel model = build_part_search_model(*base_, 1);
  std::size_t part_views = 0;
  for (const ModelBaseView& view : base_->views) part_views += view.part_index == 1;
  ASSERT_EQ(model.views.size(), part_views);
  ASSERT_EQ(model.view_centroid_mm.size(), part_views);
  for (std::size_t k = 0; k < model.views.size(); k += 37) {
    const ModelBaseView& view = base_->views[static_cast<std::size_t>(model.views[k])];
    ASSERT_EQ(view.part_index, 1);
    const ModelSurface surface(view);
    const Eigen::Vector3d centroid_view = surface.points().position_mm.rowwise().mean();
    EXPECT_LT((centroid_view - model.view_centroid_mm[k]).norm(), 1e-9);
  }
  ASSERT_FALSE(model.start_views.empty());
  for (const std::size_t s : model.start_views) {
    ASSERT_LT(s, model.views.size());
    EXPECT_TRUE(
        is_once_subdivided_view(base_->views[static_cast<std::size_t>(model.views[s])].view_index));
  }
}

// The surface sample the free-space constraint places (free_space.hpp) is the part's own, in
// its frame: at the scan's true pose none of it lies over the belt the scanner measured;
// moved the part's size across the belt, most of it does.
TEST_F(PartPoseSearch, TheSurfaceSampleLiesOverNoBeltAtTheTruePose) {
  const RecognitionParameters parameters;
  const int parts = static_cast<int>(base_->parts.size());
  const std::vector<PartSearchModel> models = search_models();
  for (std::uint64_t seed = 101; seed < 106; ++seed) {
    const int part = static_cast<int>(seed % parts);
    const Scan scene = scan(part, seed);
    ASSERT_TRUE(scene.image.belt_known());
    const Eigen::Matrix3Xd& sample = models[static_cast<std::size_t>(part)].surface_sample_mm;
    EXPECT_GE(sample.cols(), 200);
    EXPECT_LE(sample.cols(), 512);
    const GroundTruthPose& truth = *scene.image.ground_truth;
    RigidTransform T_scene_part{truth.rotation, truth.translation_mm};
    EXPECT_LE(fraction_over_belt(scene.image, sample, T_scene_part.inverse()), 0.02)
        << "seed " << seed << ", " << truth.part;
    T_scene_part.translation_mm.x() += 0.3 * base_->parts[static_cast<std::size_t>(part)].size_mm;
    EXPECT_GE(fraction_over_belt(scene.image, sample, T_scene_part.inverse()), 0.05)
        << "seed " << seed << ", " << truth.part;
  }
}

TEST_F(PartPoseSearch, QuickFitOfAnEmptySceneHasNoPoses) {
  const RecognitionParameters parameters;
  const PartSearchModel model = build_part_search_model(*base_, 0);
  EXPECT_TRUE(quick_field_poses(quick_fit_points(RegistrationPoints{}, parameters.catalog_rank),
                                *base_, model, parameters.search, parameters.catalog_rank)
                  .empty());
}

// Verification's starts (turns about one selected view's axis) from a view about 30 degrees
// from the scene's true viewing direction: aligned in the part's field, the best lands near
// the true pose, on the part's view nearest to it.
TEST_F(PartPoseSearch, AlignsTheStartsOfAViewFarFromTheTruthOntoTheNearestView) {
  const RecognitionParameters parameters;
  const int parts = static_cast<int>(base_->parts.size());
  int near_truth = 0, scans = 0;
  for (std::uint64_t seed = 201; seed < 211; ++seed, ++scans) {
    const int part = static_cast<int>(seed % parts);
    const PartSearchModel model = build_part_search_model(*base_, part);
    const Scan scene = scan(part, seed);
    const GroundTruthPose& truth = *scene.image.ground_truth;
    const Eigen::Vector3d seen_from_part = truth.rotation.transpose() * Eigen::Vector3d::UnitZ();
    int start_view = -1;
    double start_offset_deg = 180;
    for (std::size_t v = 0; v < base_->views.size(); ++v) {
      if (base_->views[v].part_index != part) continue;
      const double offset_deg =
          std::acos(std::clamp(base_->views[v].direction_part.dot(seen_from_part), -1.0, 1.0)) *
          180 / std::numbers::pi;
      if (std::abs(offset_deg - 30) < std::abs(start_offset_deg - 30))
        start_view = static_cast<int>(v), start_offset_deg = offset_deg;
    }
    ASSERT_GE(start_view, 0);
    ASSERT_NEAR(start_offset_deg, 30, 10) << seed;
    const ModelSurface start_surface(base_->views[static_cast<std::size_t>(start_view)]);
    const std::vector<RigidTransform> starts = generate_pose_hypotheses(
        scene.points, start_surface.points(), PoseFromPatches{}, {.in_plane_turns = 12});
    const std::vector<ViewPoseHypothesis> aligned =
        align_view_starts_in_field(scene.points, *base_, start_view, starts, model,
                                   parameters.field_starts, parameters.search, 2);
    ASSERT_FALSE(aligned.empty()) << seed;
    for (std::size_t k = 1; k < aligned.size(); ++k)
      EXPECT_LE(aligned[k - 1].truncated_mean_square_mm2, aligned[k].truncated_mean_square_mm2);
    const ViewPoseHypothesis& best = aligned.front();
    const ModelBaseView& view = base_->views[static_cast<std::size_t>(best.view)];
    EXPECT_EQ(view.part_index, part);
    const RigidTransform T_scanner_part = best.T_model_scene.inverse() * view.T_scanner_part;
    const Eigen::Vector3d seen_from =
        T_scanner_part.rotation.transpose() * Eigen::Vector3d::UnitZ();
    for (std::size_t v = 0; v < base_->views.size(); ++v) {
      if (base_->views[v].part_index != part) continue;
      EXPECT_GE(view.direction_part.dot(seen_from) + 1e-12,
                base_->views[v].direction_part.dot(seen_from))
          << "seed " << seed << ": view " << best.view << " is not the nearest";
    }
    const double error_deg = rotation_angle_between_rad(T_scanner_part.rotation, truth.rotation) *
                             180 / std::numbers::pi;
    near_truth += error_deg < 8.0;  // well inside what registration (ch. 6) converges from
  }
  // The 4 aligned starts came from turns 30 degrees apart about an axis 30 degrees off; the
  // best of them was within 6 degrees for 6 of these 10 scans (the 4 others landed 40-60
  // degrees away, or turned half-way round the nearly symmetric coupling).
  EXPECT_GE(near_truth, scans / 2 + 1);
}

}  // namespace
}  // namespace cosmos
