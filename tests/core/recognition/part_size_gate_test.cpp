// The size gate (part_size_gate.hpp): a part's thinnest width from its hull, in any
// orientation and where the narrowest direction meets no face; the scene's width and top as
// bounds; which parts the verdict leaves out, and when it leaves none; and which views the
// views' bound leaves out.
#include "core/recognition/part_size_gate.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>

namespace cosmos {
namespace {

Eigen::Matrix3d seeded_rotation(std::uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(random), normal(random), normal(random), normal(random));
  return q.normalized().toRotationMatrix();
}

ModelPart hull_part(const std::vector<Eigen::Vector3d>& corners, const Eigen::Matrix3d& rotation) {
  ModelPart part;
  for (const Eigen::Vector3d& corner : corners) part.hull_vertices_mm.push_back(rotation * corner);
  for (const Eigen::Vector3d& a : part.hull_vertices_mm)
    for (const Eigen::Vector3d& b : part.hull_vertices_mm)
      part.diameter_mm = std::max(part.diameter_mm, (a - b).norm());
  return part;
}

std::vector<Eigen::Vector3d> box_corners(const Eigen::Vector3d& half_mm) {
  std::vector<Eigen::Vector3d> corners;
  for (int corner = 0; corner < 8; ++corner)
    corners.emplace_back((corner & 1 ? 1 : -1) * half_mm.x(), (corner & 2 ? 1 : -1) * half_mm.y(),
                         (corner & 4 ? 1 : -1) * half_mm.z());
  return corners;
}

TEST(PartSizeGate, ABoxIsAsThinAsItsSmallestSideInAnyOrientation) {
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    const ModelPart box = hull_part(box_corners({30, 20, 4}), seeded_rotation(seed));
    const PartExtent extent = part_extent(box);
    EXPECT_NEAR(extent.thinnest_width_mm, 8.0, 0.02) << seed;
    EXPECT_GE(extent.thinnest_width_mm, 8.0 - 1e-9) << seed;
    EXPECT_DOUBLE_EQ(extent.diameter_mm, box.diameter_mm) << seed;
    EXPECT_NEAR(extent.diameter_mm, 2 * std::sqrt(30.0 * 30 + 20 * 20 + 4 * 4), 1e-9) << seed;
  }
}

// A regular tetrahedron is narrowest between two opposite edges (edge / sqrt 2), not across
// a face onto the opposite corner (edge x sqrt(2/3)): the search over directions finds it.
TEST(PartSizeGate, ATetrahedronIsNarrowestBetweenOppositeEdges) {
  const std::vector<Eigen::Vector3d> corners = {
      {10, 10, 10}, {10, -10, -10}, {-10, 10, -10}, {-10, -10, 10}};
  const double edge_mm = std::sqrt(800.0);
  for (std::uint32_t seed = 11; seed <= 15; ++seed) {
    const PartExtent extent = part_extent(hull_part(corners, seeded_rotation(seed)));
    EXPECT_NEAR(extent.thinnest_width_mm, edge_mm / std::sqrt(2.0), 0.02) << seed;
  }
}

TEST(PartSizeGate, APartWithoutAHullIsNeverTooThick) {
  ModelPart part;
  part.diameter_mm = 50;
  const PartExtent extent = part_extent(part);
  EXPECT_EQ(extent.diameter_mm, 50);
  EXPECT_EQ(extent.thinnest_width_mm, 0);
}

TEST(PartSizeGate, TheSceneWidthIsABoundOnItsPointsAndTheTopItsHighestPixel) {
  RegistrationPoints points;
  points.position_mm.resize(3, 4);
  points.position_mm << 0, 100, 0, 30,  //
      0, 0, 40, 10,                     //
      0, 0, 0, 25;
  RangeImage image(4, 3, 1.0, 1.0);
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column)
      image.z_mm(column, row) = std::numeric_limits<float>::quiet_NaN();
  image.z_mm(1, 1) = 12.5f;
  image.z_mm(3, 2) = 31.0f;
  const SceneExtent extent = scene_extent(points, image);
  const double diameter_mm = std::sqrt(100.0 * 100 + 40 * 40);  // (100,0,0) to (0,40,0)
  EXPECT_LE(extent.width_mm, diameter_mm + 1e-9);
  EXPECT_GE(extent.width_mm, 0.98 * diameter_mm);
  EXPECT_FLOAT_EQ(static_cast<float>(extent.top_mm), 31.0f);

  // Across the viewing direction: the points' widest width in the belt's plane is their
  // (100,0) to (0,40) span, their narrowest between (0,0) and the line from (100,0) to (0,40).
  EXPECT_LE(extent.widest_across_mm, diameter_mm + 1e-9);
  EXPECT_GE(extent.widest_across_mm, 0.98 * diameter_mm);
  const double narrowest_mm = 100.0 * 40 / diameter_mm;
  EXPECT_GE(extent.narrowest_across_mm, narrowest_mm - 1e-9);
  EXPECT_LE(extent.narrowest_across_mm, 1.02 * narrowest_mm);

  const SceneExtent empty = scene_extent(RegistrationPoints{}, RangeImage{});
  EXPECT_EQ(empty.width_mm, 0);
  EXPECT_EQ(empty.top_mm, 0);
  EXPECT_EQ(empty.widest_across_mm, 0);
  EXPECT_EQ(empty.narrowest_across_mm, 0);
}

TEST(PartSizeGate, ViewsTooShortOrTooNarrowForTheSceneAreLeftOutWithinTheirTolerances) {
  PartSizeGateParameters parameters;
  parameters.extent_tolerance_mm = 3;
  parameters.view_height_tolerance_mm = 1.5;
  SceneExtent scene;
  scene.top_mm = 40;
  scene.widest_across_mm = 90;
  scene.narrowest_across_mm = 50;
  const ViewSizeGate gate = view_size_gate(scene, SceneParts::kOne, true, parameters);
  EXPECT_TRUE(gate.fits({45, 100, 60}));
  EXPECT_TRUE(gate.fits({38.6, 87.1, 47.1}));  // all three within their tolerances
  EXPECT_FALSE(gate.fits({38.4, 100, 60}));    // stands lower than the scene's top
  EXPECT_FALSE(gate.fits({45, 86.9, 60}));     // narrower than the scene's widest width
  EXPECT_FALSE(gate.fits({45, 100, 46.9}));    // narrower than its narrowest
  EXPECT_TRUE(gate.fits(ViewExtent{}));        // unbounded
  // A part that need not lie on the belt may stand lower than the scene's top.
  EXPECT_TRUE(view_size_gate(scene, SceneParts::kOne, false, parameters).fits({20, 100, 60}));
  EXPECT_FALSE(view_size_gate(scene, SceneParts::kOne, false, parameters).fits({20, 80, 60}));
  // Several touching parts bound no one part's widths or height.
  EXPECT_TRUE(view_size_gate(scene, SceneParts::kOneOrMore, true, parameters).fits({20, 30, 10}));
  parameters.views = false;
  EXPECT_TRUE(view_size_gate(scene, SceneParts::kOne, true, parameters).fits({20, 30, 10}));
  parameters.views = true;
  parameters.enabled = false;
  EXPECT_TRUE(view_size_gate(scene, SceneParts::kOne, true, parameters).fits({20, 30, 10}));
}

TEST(PartSizeGate, PartsTooSmallOrTooThickAreLeftOutWithinTheirTolerances) {
  PartSizeGateParameters parameters;
  parameters.extent_tolerance_mm = 3;
  parameters.height_tolerance_mm = 5;
  const SceneExtent scene{80.0, 20.0};
  const auto verdict = [&](double diameter_mm, double thinnest_mm,
                           SceneParts parts = SceneParts::kOne, bool touch_belt = true) {
    return judge_part_size({diameter_mm, thinnest_mm}, scene, parts, touch_belt, parameters);
  };
  EXPECT_EQ(verdict(100, 10), SizeVerdict::kFits);
  EXPECT_EQ(verdict(77.5, 10), SizeVerdict::kFits);  // within the extent tolerance
  EXPECT_EQ(verdict(76.5, 10), SizeVerdict::kSmallerThanScene);
  EXPECT_EQ(verdict(100, 24.5), SizeVerdict::kFits);  // within the height tolerance
  EXPECT_EQ(verdict(100, 25.5), SizeVerdict::kThickerThanScene);
  // Several parts may make up the scene's width, but each lies on the belt.
  EXPECT_EQ(verdict(40, 10, SceneParts::kOneOrMore), SizeVerdict::kFits);
  EXPECT_EQ(verdict(40, 30, SceneParts::kOneOrMore), SizeVerdict::kThickerThanScene);
  // A part that need not touch the belt can be any thickness.
  EXPECT_EQ(verdict(100, 60, SceneParts::kOne, false), SizeVerdict::kFits);
  parameters.enabled = false;
  EXPECT_EQ(verdict(10, 60), SizeVerdict::kFits);
}

}  // namespace
}  // namespace cosmos
