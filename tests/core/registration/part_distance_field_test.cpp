// The part distance field against surfaces whose distance is known in closed form (a plane,
// a sphere), and its Gauss-Newton alignment recovering a known displacement of an
// asymmetric surface, and held on the belt where the surface leaves a slide free.
#include "core/registration/part_distance_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace cosmos {
namespace {

constexpr double kVoxelMm = 2.0;
// Distances are to the centres of the voxels holding points: off by up to half a diagonal.
constexpr double kHalfDiagonalMm = 0.87 * kVoxelMm;

std::vector<Eigen::Vector3d> plane_points() {
  std::vector<Eigen::Vector3d> points;
  for (double x = -30; x <= 30; x += 0.5)
    for (double y = -30; y <= 30; y += 0.5) points.emplace_back(x, y, 0.0);
  return points;
}

std::vector<Eigen::Vector3d> sphere_points(double radius_mm) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 20000; ++i) {
    // A Fibonacci lattice: evenly spread, deterministic.
    const double z = 1.0 - 2.0 * (i + 0.5) / 20000;
    const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
    const double r = std::sqrt(1.0 - z * z);
    points.emplace_back(radius_mm * r * std::cos(phi), radius_mm * r * std::sin(phi),
                        radius_mm * z);
  }
  return points;
}

// Height of a lopsided bump field: no rotation or shift maps it onto itself.
double relief_mm(double x, double y) {
  return 8.0 * std::exp(-((x - 8) * (x - 8) + (y + 5) * (y + 5)) / 60.0) +
         5.0 * std::exp(-((x + 12) * (x + 12) + (y - 10) * (y - 10)) / 30.0) + 0.1 * x;
}

std::vector<Eigen::Vector3d> relief_points(double step_mm) {
  std::vector<Eigen::Vector3d> points;
  for (double x = -30; x <= 30; x += step_mm)
    for (double y = -30; y <= 30; y += step_mm) points.emplace_back(x, y, relief_mm(x, y));
  return points;
}

RegistrationPoints as_scene(const std::vector<Eigen::Vector3d>& points) {
  RegistrationPoints scene;
  scene.position_mm.resize(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    scene.position_mm.col(static_cast<Eigen::Index>(i)) = points[i];
  return scene;
}

TEST(PartDistanceField, PlaneDistanceIsTheHeightWithinHalfAVoxel) {
  const PartDistanceField field(plane_points(), {.voxel_mm = kVoxelMm, .margin_mm = 12});
  ASSERT_FALSE(field.empty());
  for (double z : {-9.0, -4.3, -1.0, 0.0, 2.5, 7.7}) {
    for (double x : {-20.0, 0.3, 13.1}) {
      Eigen::Vector3d gradient;
      const double d = field.distance_mm({x, x / 2, z}, gradient);
      EXPECT_NEAR(d, std::abs(z), 0.5 * kVoxelMm) << x << " " << z;
      if (std::abs(z) > kVoxelMm) {
        EXPECT_NEAR(gradient.z(), z > 0 ? 1.0 : -1.0, 0.05) << z;
        EXPECT_NEAR(gradient.head<2>().norm(), 0.0, 0.05) << z;
      }
    }
  }
  // Beyond the grid the distance keeps growing.
  EXPECT_GT(field.distance_mm({0, 0, 40}), 30.0);
}

TEST(PartDistanceField, SphereDistanceIsRadialWithinHalfAVoxelDiagonal) {
  const double radius_mm = 25;
  const PartDistanceField field(sphere_points(radius_mm), {.voxel_mm = kVoxelMm, .margin_mm = 12});
  for (const Eigen::Vector3d& direction : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.6, 0.8, 0),
                                           Eigen::Vector3d(-1.0 / 3, 2.0 / 3, 2.0 / 3)}) {
    for (double r : {5.0, 15.0, 24.0, 25.0, 28.0, 33.0})
      EXPECT_NEAR(field.distance_mm(r * direction), std::abs(r - radius_mm), kHalfDiagonalMm) << r;
  }
}

// 16 bits per voxel, in steps of the grid's largest distance / 65535: the sphere's distances
// keep the accuracy of the voxels (within a voxel diagonal where the interpolation spans
// voxels a half diagonal off each way, as at its centre).
TEST(PartDistanceField, KeepsTwoBytesPerVoxel) {
  const double radius_mm = 25.0;
  const PartDistanceField field(sphere_points(radius_mm), {.voxel_mm = kVoxelMm, .margin_mm = 12});
  EXPECT_EQ(field.memory_bytes(), 2 * field.voxel_count());
  EXPECT_NEAR(field.distance_mm(Eigen::Vector3d::Zero()), radius_mm, 2 * kHalfDiagonalMm);
  for (double r : {24.0, 25.0, 26.0})
    EXPECT_NEAR(field.distance_mm(Eigen::Vector3d(0, r, 0)), std::abs(r - radius_mm),
                kHalfDiagonalMm)
        << r;
}

TEST(PartDistanceField, TruncatedMeanSquareIsSmallOnTheSurfaceAndCappedFarFromIt) {
  const std::vector<Eigen::Vector3d> surface = relief_points(0.5);
  const PartDistanceField field(surface, {.voxel_mm = kVoxelMm, .margin_mm = 12});
  const RegistrationPoints scene = as_scene(relief_points(3.0));
  EXPECT_LT(field_truncated_mean_square_mm2(scene, field, RigidTransform{}, 10.0), 0.25);
  const RigidTransform far{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 60)};
  EXPECT_DOUBLE_EQ(field_truncated_mean_square_mm2(scene, field, far, 10.0), 100.0);
}

// A score asked to stop above a bound is the exact mean when the mean is within it (to the
// last bit), and some value above the bound when it is not.
TEST(PartDistanceField, ABoundedScoreIsExactWithinItsBoundAndAboveItOtherwise) {
  const PartDistanceField field(relief_points(0.5), {.voxel_mm = kVoxelMm, .margin_mm = 12});
  const RegistrationPoints scene = as_scene(relief_points(3.0));
  const RigidTransform lifted{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 4)};
  const double mean_mm2 = field_truncated_mean_square_mm2(scene, field, lifted, 10.0);
  ASSERT_GT(mean_mm2, 4.0);
  EXPECT_EQ(field_truncated_mean_square_mm2(scene, field, lifted, 10.0, mean_mm2), mean_mm2);
  EXPECT_EQ(field_truncated_mean_square_mm2(scene, field, lifted, 10.0, 2 * mean_mm2), mean_mm2);
  for (double bound_mm2 : {0.0, 1.0, 0.5 * mean_mm2}) {
    const double abandoned = field_truncated_mean_square_mm2(scene, field, lifted, 10.0, bound_mm2);
    EXPECT_GT(abandoned, bound_mm2) << bound_mm2;
    EXPECT_NE(abandoned, mean_mm2) << bound_mm2;
  }
}

// Half the scene moved 6 mm off the surface: half of it is within the gate's 2 mm, so the
// gate at 0.5 just passes it, and at 0.6 not; all of it moved off fails.
TEST(PartDistanceField, FractionWithinCountsThePointsNearTheSurface) {
  const PartDistanceField field(relief_points(0.5), {.voxel_mm = kVoxelMm, .margin_mm = 12});
  std::vector<Eigen::Vector3d> points = relief_points(3.0);
  for (std::size_t i = 0; i < points.size(); i += 2) points[i].z() += 6.0;
  const RegistrationPoints scene = as_scene(points);
  const double within = field_fraction_within(scene, field, RigidTransform{}, 2.0);
  EXPECT_NEAR(within, 0.5, 0.5 / static_cast<double>(points.size()) + 1e-12);
  EXPECT_TRUE((FieldGate{.distance_mm = 2.0, .min_fraction = within}.passes(scene, field,
                                                                            RigidTransform{})));
  EXPECT_FALSE(
      (FieldGate{.distance_mm = 2.0, .min_fraction = 0.6}.passes(scene, field, RigidTransform{})));
  const RigidTransform off{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 6)};
  EXPECT_DOUBLE_EQ(field_fraction_within(scene, field, off, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(field_fraction_within(RegistrationPoints{}, field, RigidTransform{}, 2.0), 0.0);
}

// A lumpy ellipsoid (no symmetry): the whole of it in the field, its upper half (what a
// scanner above it sees) as the scene.
std::vector<Eigen::Vector3d> lumpy_ellipsoid(int count, bool upper_half_only) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / count;
    const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
    const double r = std::sqrt(1.0 - z * z);
    const Eigen::Vector3d unit(r * std::cos(phi), r * std::sin(phi), z);
    const double lump =
        1.0 + 0.25 * std::exp(-(unit - Eigen::Vector3d(0.6, 0.3, 0.74)).squaredNorm() / 0.1);
    const Eigen::Vector3d point(30 * unit.x() * lump, 20 * unit.y() * lump, 12 * unit.z() * lump);
    if (!upper_half_only || point.z() > 0) points.push_back(point);
  }
  return points;
}

TEST(PartDistanceField, AlignmentUndoesAKnownDisplacement) {
  const PartDistanceField field(lumpy_ellipsoid(40000, false),
                                {.voxel_mm = kVoxelMm, .margin_mm = 12});
  const RegistrationPoints scene = as_scene(lumpy_ellipsoid(400, true));
  const RigidTransform displaced{
      Eigen::AngleAxisd(10 * std::numbers::pi / 180, Eigen::Vector3d(0.2, 0.3, 1).normalized())
          .matrix(),
      Eigen::Vector3d(3.0, -2.0, 2.0)};
  const double before = field_truncated_mean_square_mm2(scene, field, displaced, 10.0);
  const RigidTransform aligned = align_in_distance_field(scene, field, displaced, 15, 10.0);
  const double after = field_truncated_mean_square_mm2(scene, field, aligned, 10.0);
  EXPECT_LT(after, 0.1 * before);
  EXPECT_LT(rotation_angle_between_rad(aligned.rotation, Eigen::Matrix3d::Identity()) * 180 /
                std::numbers::pi,
            1.5);
  EXPECT_LT(aligned.translation_mm.norm(), 0.7);
}

// A block's wall seen alone leaves the block free to slide along it: the scene's points fit as
// well 4 mm higher, where the block sinks 4 mm into the belt. Held on the belt by its lowest
// corners, the alignment lifts it back onto it; free of the belt, the pose stays.
TEST(PartDistanceField, AlignmentHeldOnTheBeltStopsASlideAlongAWall) {
  std::vector<Eigen::Vector3d> wall, seen, corners;
  for (double y = -20; y <= 20; y += 0.5)
    for (double z = 0; z <= 20; z += 0.5) {
      wall.emplace_back(0.0, y, z);
      if (z >= 2 && z <= 14) seen.emplace_back(0.0, y, z);
    }
  for (const double x : {-10.0, 0.0})
    for (const double y : {-20.0, 20.0})
      for (const double z : {0.0, 20.0}) corners.emplace_back(x, y, z);
  const PartDistanceField field(wall, {.voxel_mm = kVoxelMm, .margin_mm = 12});
  const RegistrationPoints scene = as_scene(seen);
  const RigidTransform slid{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 4.0)};
  const RigidTransform free = align_in_distance_field(scene, field, slid, 10, 10.0);
  const RigidTransform held = align_in_distance_field(scene, field, slid, 10, 10.0,
                                                      {corners, RigidTransform::identity(), 1.0});
  EXPECT_GT(free.translation_mm.z(), 3.9);
  EXPECT_LT(std::abs(held.translation_mm.z()), 0.05);
  EXPECT_LT(rotation_angle_between_rad(held.rotation, Eigen::Matrix3d::Identity()), 1e-3);
  EXPECT_LT(field_truncated_mean_square_mm2(scene, field, held, 10.0), 0.5);
}

TEST(PartDistanceField, NoPointsGiveAnEmptyFieldThatAlignsNothing) {
  const PartDistanceField field({}, {});
  EXPECT_TRUE(field.empty());
  const RegistrationPoints scene = as_scene(relief_points(5.0));
  const RigidTransform start{Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 2, 3)};
  const RigidTransform aligned = align_in_distance_field(scene, field, start, 5, 10.0);
  EXPECT_EQ(aligned.translation_mm, start.translation_mm);
  EXPECT_DOUBLE_EQ(field_truncated_mean_square_mm2(scene, field, start, 10.0), 100.0);
}

// Points a kilometre and more apart (a crafted model base) would ask for a grid of 10^18
// voxels at 2 mm, its size in int overflowing: the grid stays within its bound, coarser, and
// still finds the points.
TEST(PartDistanceField, AbsurdlySpreadPointsGetABoundedCoarserGrid) {
  const std::vector<Eigen::Vector3d> points = {Eigen::Vector3d::Zero(),
                                               Eigen::Vector3d(1e9, -1e9, 1e9)};
  const PartDistanceField field(points, {});
  ASSERT_FALSE(field.empty());
  EXPECT_LE(field.voxel_count(), PartDistanceField::kMaxVoxels);
  EXPECT_GT(field.voxel_count(), PartDistanceField::kMaxVoxels / 4);
  EXPECT_GT(field.voxel_mm(), 2.0);
  EXPECT_LT(field.distance_mm(points[0]), field.voxel_mm());
  EXPECT_LT(field.distance_mm(points[1]), field.voxel_mm());
}

TEST(PartDistanceField, NonFinitePointsAreIgnoredAndExtremeOnesLeaveItEmpty) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PartDistanceField with_nan({Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d(1, 2, 3)}, {});
  ASSERT_FALSE(with_nan.empty());
  EXPECT_NEAR(with_nan.distance_mm(Eigen::Vector3d(1, 2, 3)), 0.0, 1e-6);
  // Their extent overflows a double: no grid can span it.
  const PartDistanceField extreme({Eigen::Vector3d(-1e308, 0, 0), Eigen::Vector3d(1e308, 0, 0)},
                                  {});
  EXPECT_TRUE(extreme.empty());
}

TEST(PartDistanceField, ASinglePointWithoutMarginStillInterpolates) {
  PartDistanceFieldParameters parameters;
  parameters.margin_mm = 0;
  const PartDistanceField field({Eigen::Vector3d(4, 5, 6)}, parameters);
  ASSERT_FALSE(field.empty());
  EXPECT_EQ(field.voxel_count(), 8u);
  EXPECT_NEAR(field.distance_mm(Eigen::Vector3d(4, 5, 6)), 0.0, 1e-6);
  // The edge voxel's 2 mm in 16-bit steps of the grid's largest distance (its diagonal,
  // 3.5 mm) / 65535: within half a step, 2.7e-5 mm.
  EXPECT_NEAR(field.distance_mm(Eigen::Vector3d(4, 5, 16)), 10.0, 2.7e-5);
}

}  // namespace
}  // namespace cosmos
