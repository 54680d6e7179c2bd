// Part poses on the belt: the Euler convention, uniform random rotations, placement on the
// belt, and resting poses on stable convex-hull faces drawn in proportion to solid angle.
#include "sim/part_pose.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/convex_hull.hpp"
#include "sim/procedural_meshes.hpp"
#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

void expect_rotation(const Eigen::Matrix3d& R) {
  EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
}

TEST(PartPose, EulerAnglesApplyXThenYThenZ) {
  // Rx(90) takes y to z, then Ry(90) takes z to x.
  const Eigen::Vector3d turned = rotation_from_xyz_deg(90, 90, 0) * Eigen::Vector3d::UnitY();
  EXPECT_LT((turned - Eigen::Vector3d::UnitX()).norm(), 1e-12);
  const Eigen::Matrix3d R = rotation_from_xyz_deg(10, -20, 30);
  const Eigen::Matrix3d expected =
      (Eigen::AngleAxisd(30 * std::numbers::pi / 180, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(-20 * std::numbers::pi / 180, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(10 * std::numbers::pi / 180, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  EXPECT_LT((R - expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(PartPose, RandomRotationsAreUniformAndSeeded) {
  EXPECT_EQ(random_rotation(5), random_rotation(5));
  EXPECT_NE(random_rotation(5), random_rotation(6));
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_square = Eigen::Vector3d::Zero();
  const int n = 4000;
  for (int k = 0; k < n; ++k) {
    const Eigen::Matrix3d R = random_rotation(mix_seed(77, static_cast<std::uint64_t>(k)));
    expect_rotation(R);
    const Eigen::Vector3d z = R.col(2);
    mean += z;
    mean_square += z.cwiseProduct(z);
  }
  mean /= n;
  mean_square /= n;
  // A uniform direction has mean 0 and E[z_i^2] = 1/3 (standard errors 0.009 and 0.005).
  EXPECT_LT(mean.norm(), 0.05);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(mean_square(i), 1.0 / 3.0, 0.02);
}

TEST(PartPose, PlacedOnTheBeltCentredAtTheGivenPoint) {
  const TriangleMesh box = make_box(30, 20, 10);
  const Eigen::Isometry3d T = place_on_belt(box, rotation_from_xyz_deg(20, 30, 40), 12.0, -7.0);
  Eigen::AlignedBox3d placed;
  for (const Eigen::Vector3f& v : box.vertices) placed.extend(T * v.cast<double>());
  EXPECT_NEAR(placed.min().z(), 0.0, 1e-12);
  EXPECT_NEAR(placed.center().x(), 12.0, 1e-12);
  EXPECT_NEAR(placed.center().y(), -7.0, 1e-12);
}

TEST(ConvexHull, BoxHasSixFacesAndItsVolume) {
  const ConvexHull hull = convex_hull(make_box(40, 20, 10).vertices);
  EXPECT_EQ(hull.faces.size(), 6u);
  EXPECT_NEAR(hull.volume, 8000.0, 1e-6);
  EXPECT_LT(hull.centroid.norm(), 1e-9);
  double total = 0.0;
  for (const HullFace& face : hull.faces) {
    EXPECT_EQ(face.corners.size(), 4u);
    EXPECT_TRUE(projects_inside(face, hull.centroid));
    total += solid_angle(face, hull.centroid);
  }
  EXPECT_NEAR(total, 4.0 * std::numbers::pi, 1e-9);
}

// The faces of the part lying on the belt: the hull corners at the lowest height.
int corners_on_belt(const TriangleMesh& mesh, const Eigen::Matrix3d& R) {
  const Eigen::Isometry3d T = place_on_belt(mesh, R);
  int count = 0;
  for (const Eigen::Vector3f& v : mesh.vertices) count += (T * v.cast<double>()).z() < 1e-6;
  return count;
}

TEST(PartPose, RestingBoxLiesOnAFaceChosenBySolidAngle) {
  const TriangleMesh box = make_box(40, 20, 10);
  const int n = 600;
  int on_largest_face = 0;
  for (int seed = 0; seed < n; ++seed) {
    const Eigen::Matrix3d R = resting_rotation(box, static_cast<std::uint64_t>(seed));
    expect_rotation(R);
    ASSERT_EQ(corners_on_belt(box, R), 4) << "seed " << seed;
    const Eigen::Isometry3d T = place_on_belt(box, R);
    Eigen::AlignedBox3d placed;
    for (const Eigen::Vector3f& v : box.vertices) placed.extend(T * v.cast<double>());
    on_largest_face += std::abs(placed.max().z() - 10.0) < 1e-6;
  }
  // Solid angle of a 2a x 2b face at distance d: 4 asin(ab / sqrt((a² + d²)(b² + d²))).
  const double a = 20.0;
  const double b = 10.0;
  const double d = 5.0;
  const double omega = 4.0 * std::asin(a * b / std::sqrt((a * a + d * d) * (b * b + d * d)));
  const double expected = 2.0 * omega / (4.0 * std::numbers::pi);
  EXPECT_NEAR(static_cast<double>(on_largest_face) / n, expected, 0.06);  // 3 standard errors
}

TEST(PartPose, RestingNeverUsesAnUnstableFace) {
  // A flat tetrahedron leaning out: its centroid (1, 1, 0.125) projects outside the base
  // triangle (0,0,0) (1,0,0) (0,1,0), so it can never rest on that face.
  TriangleMesh tetrahedron;
  tetrahedron.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 3, 0.5f}};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  for (int seed = 0; seed < 100; ++seed) {
    const Eigen::Matrix3d R = resting_rotation(tetrahedron, static_cast<std::uint64_t>(seed));
    const Eigen::Isometry3d T = place_on_belt(tetrahedron, R);
    int base_on_belt = 0;
    for (int v = 0; v < 3; ++v)
      base_on_belt +=
          (T * tetrahedron.vertices[static_cast<std::size_t>(v)].cast<double>()).z() < 1e-6;
    EXPECT_LT(base_on_belt, 3) << "seed " << seed;
  }
}

TEST(PartPose, AStableBoxHasSixRestingPosesLikeliestOnItsLargestFaces) {
  const TriangleMesh box = make_box(40, 20, 10);
  const std::vector<StableRestingPose> poses = stable_resting_poses(box, {});
  ASSERT_EQ(poses.size(), 6u);
  double total = 0;
  for (const StableRestingPose& pose : poses) {
    expect_rotation(pose.R_belt_part);
    ASSERT_EQ(corners_on_belt(box, pose.R_belt_part), 4);
    // The box is centred on its origin: the origin rests at half the extent along the
    // vertical.
    Eigen::AlignedBox3d placed;
    for (const Eigen::Vector3f& v : box.vertices)
      placed.extend(pose.R_belt_part * v.cast<double>());
    EXPECT_NEAR(pose.height_mm, -placed.min().z(), 1e-9);
    total += pose.probability;
  }
  EXPECT_NEAR(total, 1.0, 1e-9);
  // The two 40 x 20 faces first, with the chance resting_rotation draws them with.
  EXPECT_NEAR(poses[0].height_mm, 5.0, 1e-6);
  EXPECT_NEAR(poses[1].height_mm, 5.0, 1e-6);
  EXPECT_NEAR(poses[5].height_mm, 20.0, 1e-6);
  const double a = 20.0;
  const double b = 10.0;
  const double d = 5.0;
  const double omega = 4.0 * std::asin(a * b / std::sqrt((a * a + d * d) * (b * b + d * d)));
  EXPECT_NEAR(poses[0].probability, omega / (4.0 * std::numbers::pi), 1e-9);
}

TEST(PartPose, AHullHasEachCornerOnce) {
  const std::vector<Eigen::Vector3d> box = hull_vertices(make_box(40, 20, 10));
  ASSERT_EQ(box.size(), 8u);
  for (const Eigen::Vector3d& corner : box)
    EXPECT_LT((corner.cwiseAbs() - Eigen::Vector3d(20, 10, 5)).norm(), 1e-5);
  TriangleMesh square;
  square.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(hull_vertices(square).size(), 4u);
}

TEST(PartPose, RestingPosesMergeNearFacesAndKeepTheLikeliest) {
  // A once-subdivided icosphere rests on any of its 80 faces, neighbours about 20 degrees
  // apart: each its own pose unless the merge angle joins them, the chances always summing
  // to one.
  const TriangleMesh sphere = make_icosphere(20, 1);
  const auto total = [](const std::vector<StableRestingPose>& poses) {
    double sum = 0;
    for (const StableRestingPose& pose : poses) sum += pose.probability;
    return sum;
  };
  const std::vector<StableRestingPose> apart =
      stable_resting_poses(sphere, {.merge_deg = 8, .max_poses = 1000, .min_probability = 0});
  EXPECT_EQ(apart.size(), 80u);
  EXPECT_NEAR(total(apart), 1.0, 1e-9);
  const std::vector<StableRestingPose> merged =
      stable_resting_poses(sphere, {.merge_deg = 30, .max_poses = 1000, .min_probability = 0});
  EXPECT_LT(merged.size(), 40u);
  EXPECT_GT(merged.size(), 4u);
  EXPECT_NEAR(total(merged), 1.0, 1e-9);
  EXPECT_GT(merged[0].probability, 1.5 / 80);
  const std::vector<StableRestingPose> likeliest =
      stable_resting_poses(sphere, {.merge_deg = 30, .max_poses = 3, .min_probability = 0});
  ASSERT_EQ(likeliest.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_DOUBLE_EQ(likeliest[k].probability, merged[k].probability);
}

TEST(PartPose, CentreOfMassOfClosedAndFlatMeshes) {
  TriangleMesh box = make_box(40, 20, 10);
  for (Eigen::Vector3f& v : box.vertices) v += Eigen::Vector3f(1, 2, 3);
  EXPECT_LT((centre_of_mass(box) - Eigen::Vector3d(1, 2, 3)).norm(), 1e-5);
  TriangleMesh square;
  square.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_LT((centre_of_mass(square) - Eigen::Vector3d(1, 1, 0)).norm(), 1e-9);
  // A flat part lies on its plane.
  const Eigen::Matrix3d R = resting_rotation(square, 3);
  EXPECT_NEAR(std::abs((R * Eigen::Vector3d::UnitZ()).z()), 1.0, 1e-12);
}

}  // namespace
}  // namespace cosmos
