// The voxels of a part's surface: each point in the voxel it rounds to, the runs covering the
// grid exactly, the distance field built from them the same as from the points, and grids the
// consistency check must refuse (what the model-base reader relies on).
#include "core/registration/part_surface_voxels.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "core/registration/part_distance_field.hpp"

namespace cosmos {
namespace {

// Points on a lumpy closed surface, seeded: many share a voxel, many do not.
std::vector<Eigen::Vector3d> lumpy_surface_points() {
  std::mt19937 generator(17);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 6000; ++i) {
    const Eigen::Vector3d direction =
        Eigen::Vector3d(normal(generator), normal(generator), normal(generator)).normalized();
    const double radius_mm = 20.0 + 4.0 * std::sin(3 * direction.x()) * std::cos(2 * direction.z());
    points.push_back(radius_mm * direction.cwiseProduct(Eigen::Vector3d(1.5, 1.0, 0.6)));
  }
  return points;
}

TEST(PartSurfaceVoxels, EachPointOccupiesTheVoxelItRoundsToAndTheRunsCoverTheGrid) {
  const std::vector<Eigen::Vector3d> points = lumpy_surface_points();
  const PartDistanceFieldParameters parameters;
  const PartSurfaceVoxels voxels = part_surface_voxels(points, parameters);
  ASSERT_FALSE(voxels.empty());
  EXPECT_TRUE(part_surface_voxels_consistent(voxels));
  EXPECT_EQ(voxels.voxel_mm, parameters.voxel_mm);
  std::set<std::tuple<long, long, long>> rounded;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d u = (p - voxels.origin_mm) / voxels.voxel_mm;
    rounded.emplace(std::lround(u.x()), std::lround(u.y()), std::lround(u.z()));
  }
  EXPECT_EQ(voxels.occupied_voxels, rounded.size());
  EXPECT_LT(voxels.occupied_voxels, points.size());
  // The margin on every side: the lowest point's voxel is margin / voxel in from the origin.
  const auto [x, y, z] = *rounded.begin();
  EXPECT_EQ(x, std::lround(parameters.margin_mm / parameters.voxel_mm));
  EXPECT_GE(y, 0);
  EXPECT_GE(z, 0);
}

TEST(PartSurfaceVoxels, TheFieldOfTheVoxelsIsTheFieldOfThePoints) {
  const std::vector<Eigen::Vector3d> points = lumpy_surface_points();
  const PartDistanceFieldParameters parameters;
  const PartDistanceField from_points(points, parameters);
  const PartDistanceField from_voxels(part_surface_voxels(points, parameters));
  ASSERT_FALSE(from_voxels.empty());
  EXPECT_EQ(from_voxels.voxel_count(), from_points.voxel_count());
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> coordinate(-45.0, 45.0);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d q(coordinate(generator), coordinate(generator), coordinate(generator));
    Eigen::Vector3d gradient_points, gradient_voxels;
    EXPECT_EQ(from_voxels.distance_mm(q, gradient_voxels),
              from_points.distance_mm(q, gradient_points));
    EXPECT_EQ(gradient_voxels, gradient_points);
  }
  // Near the surface the field says so: a point of it is within half a voxel diagonal.
  EXPECT_LT(from_voxels.distance_mm(points[10]), 0.87 * parameters.voxel_mm);
}

TEST(PartSurfaceVoxels, NonFinitePointsAreLeftOutAndNoFinitePointGivesNoVoxels) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PartSurfaceVoxels one = part_surface_voxels(
      {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d(0, 0, INFINITY)}, {});
  EXPECT_EQ(one.occupied_voxels, 1u);
  EXPECT_TRUE(part_surface_voxels_consistent(one));
  const PartSurfaceVoxels none = part_surface_voxels({Eigen::Vector3d(nan, 1, 1)}, {});
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(part_surface_voxels_consistent(none));
  EXPECT_TRUE(PartDistanceField(none).empty());
  PartDistanceFieldParameters no_voxel;
  no_voxel.voxel_mm = 0;
  EXPECT_TRUE(part_surface_voxels({Eigen::Vector3d(1, 2, 3)}, no_voxel).empty());
}

TEST(PartSurfaceVoxels, GridsTheRunsDoNotDescribeAreRefusedAndGiveNoField) {
  const PartSurfaceVoxels good = part_surface_voxels(lumpy_surface_points(), {});
  ASSERT_TRUE(part_surface_voxels_consistent(good));
  const auto refused = [](PartSurfaceVoxels voxels) {
    return !part_surface_voxels_consistent(voxels) && PartDistanceField(voxels).empty();
  };
  PartSurfaceVoxels damaged = good;
  ++damaged.occupied_voxels;
  EXPECT_TRUE(refused(damaged));
  damaged = good;
  damaged.occupied_runs.resize(good.occupied_runs.size() / 2);
  EXPECT_TRUE(refused(damaged));
  damaged = good;
  ++damaged.size[1];  // the runs end before the grid does
  EXPECT_TRUE(refused(damaged));
  damaged = good;
  damaged.size[2] = 1;
  EXPECT_TRUE(refused(damaged));
  damaged = good;
  damaged.size = {1 << 10, 1 << 10, 1 << 5};  // 32 Mi voxels
  EXPECT_TRUE(refused(damaged));
  damaged = good;
  damaged.voxel_mm = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(refused(damaged));
  damaged = good;
  damaged.origin_mm.x() = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(refused(damaged));
}

}  // namespace
}  // namespace cosmos
