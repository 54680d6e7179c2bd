// Whether a pose rests on the belt (check_resting): a 40 x 20 x 10 mm box, its six resting
// poses and its hull's corners, in poses that rest, float, sink or lean. And the search's
// starts (resting_pose_hypotheses) on scans of the regression catalog's parts lying in their
// two likeliest resting poses: the true pose is among the poses it returns.
#include "core/recognition/resting_pose_search.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <numbers>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "core/representation/cosmos_pipeline.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_scan.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

ModelPart box_part(int resting_poses_kept) {
  ModelPart part;
  part.name = "box";
  for (double x : {-20.0, 20.0})
    for (double y : {-10.0, 10.0})
      for (double z : {-5.0, 5.0}) part.hull_vertices_mm.emplace_back(x, y, z);
  // Face down: -z, +z, -y, +y, -x, +x; the larger faces likelier.
  const Eigen::Matrix3d flip =
      Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d y_down =
      Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d x_down =
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const std::vector<RestingPose> all = {{Eigen::Matrix3d::Identity(), 5, 0.3},
                                        {flip, 5, 0.3},
                                        {y_down, 10, 0.15},
                                        {flip * y_down, 10, 0.15},
                                        {x_down, 20, 0.05},
                                        {flip * x_down, 20, 0.05}};
  part.resting_poses.assign(all.begin(), all.begin() + resting_poses_kept);
  return part;
}

// T_part_scene of the box lying with `R_belt_part`, turned about the vertical and moved on
// the belt, its origin `lift_mm` above its resting height.
RigidTransform lying(const RestingPose& pose, double turn_deg, double lift_mm) {
  RigidTransform T_scene_part;
  T_scene_part.rotation =
      Eigen::AngleAxisd(turn_deg * kDegree, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
      pose.R_belt_part;
  T_scene_part.translation_mm = Eigen::Vector3d(12, -30, pose.height_mm + lift_mm);
  return T_scene_part.inverse();
}

TEST(RestingPoseSearch, APoseOnAStableFaceTurnedAnywhereRests) {
  const ModelPart part = box_part(6);
  for (const RestingPose& pose : part.resting_poses)
    for (double turn_deg : {0.0, 37.0, 190.0}) {
      const RestingCheck check = check_resting(part, lying(pose, turn_deg, 0), {});
      EXPECT_TRUE(check.at_rest);
      EXPECT_TRUE(check.covered);
      EXPECT_NEAR(check.lowest_point_mm, 0, 1e-9);
      EXPECT_NEAR(check.tilt_deg, 0, 1e-4);
    }
}

TEST(RestingPoseSearch, AFloatingOrSunkenPartDoesNotRest) {
  const ModelPart part = box_part(6);
  const RestingSearchParameters parameters;
  const RestingCheck floating =
      check_resting(part, lying(part.resting_poses[2], 10, 3), parameters);
  EXPECT_FALSE(floating.at_rest);
  EXPECT_NEAR(floating.lowest_point_mm, 3, 1e-9);
  const RestingCheck sunk = check_resting(part, lying(part.resting_poses[0], 10, -3), parameters);
  EXPECT_FALSE(sunk.at_rest);
  EXPECT_NEAR(sunk.lowest_point_mm, -3, 1e-9);
  EXPECT_TRUE(check_resting(part, lying(part.resting_poses[0], 10, 1.5), parameters).at_rest);
}

TEST(RestingPoseSearch, ALeaningPartTouchingTheBeltDoesNotRestUnlessItsPosesAreUnknown) {
  // Tilted 20 degrees about the box's long axis and lowered onto the belt: one edge touches.
  RigidTransform T_scene_part;
  T_scene_part.rotation =
      Eigen::AngleAxisd(20 * kDegree, Eigen::Vector3d::UnitX()).toRotationMatrix();
  double lowest = 0;
  for (const Eigen::Vector3d& corner : box_part(6).hull_vertices_mm)
    lowest = std::min(lowest, (T_scene_part.rotation * corner).z());
  T_scene_part.translation_mm = Eigen::Vector3d(0, 0, -lowest);
  const RestingCheck leaning = check_resting(box_part(6), T_scene_part.inverse(), {});
  EXPECT_NEAR(leaning.lowest_point_mm, 0, 1e-9);
  EXPECT_NEAR(leaning.tilt_deg, 20, 1e-6);
  EXPECT_FALSE(leaning.at_rest);
  // With only the two likeliest poses kept (60 % of the chance) the part's stable poses are
  // not known well enough to refuse a lean: the contact alone decides.
  const RestingCheck uncovered = check_resting(box_part(2), T_scene_part.inverse(), {});
  EXPECT_FALSE(uncovered.covered);
  EXPECT_TRUE(uncovered.at_rest);
}

TEST(RestingPoseSearch, TheTruePoseOfAPartLyingInAStablePoseIsAmongTheStarts) {
  const ModelBase base = read_model_base(testing::regression_model_base());
  const PartCatalog catalog =
      read_part_catalog(std::filesystem::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml");
  const RecognitionParameters parameters;
  int scans = 0;
  for (int part = 0; part < static_cast<int>(base.parts.size()); ++part) {
    const ModelPart& model_part = base.parts[static_cast<std::size_t>(part)];
    const PartEntry& entry = catalog.at(model_part.name);
    const TriangleMesh mesh = load_mesh(entry.mesh_path, entry.size_mm);
    const PartSearchModel model = build_part_search_model(base, part);
    for (std::size_t pose = 0; pose < 2 && pose < model_part.resting_poses.size(); ++pose) {
      const double turn_rad = (37.0 + 71.0 * part + 113.0 * pose) * kDegree;
      const Eigen::Matrix3d R_belt_part =
          Eigen::AngleAxisd(turn_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
          model_part.resting_poses[pose].R_belt_part;
      const RangeImage image = scan_single_part(mesh, model_part.name, R_belt_part,
                                                ScannerParameters{}, ConditioningParameters{});
      const ViewAnalysis analysis = analyze_view(image, CosmosParameters{});
      const RegistrationPoints points =
          build_registration_points(image, parameters.scene_points, &analysis.frames).points;
      const RigidTransform T_part_scene_true =
          RigidTransform{image.ground_truth->rotation, image.ground_truth->translation_mm}
              .inverse();
      const std::vector<FieldHypothesis> starts =
          resting_pose_hypotheses(points, base, part, model, parameters.search, parameters.resting);
      ++scans;
      bool among = false;
      for (const FieldHypothesis& start : starts) {
        const Eigen::AngleAxisd off(start.T_part_scene.rotation *
                                    T_part_scene_true.rotation.transpose());
        const Eigen::Vector3d origin_scene = T_part_scene_true.inverse().translation_mm;
        const double offset_mm =
            (start.T_part_scene.apply(origin_scene) - T_part_scene_true.apply(origin_scene)).norm();
        among |= off.angle() < 5 * kDegree && offset_mm < 3;
      }
      EXPECT_TRUE(among) << model_part.name << ", resting pose " << pose;
    }
  }
  EXPECT_GE(scans, 8);
}

}  // namespace
}  // namespace cosmos
