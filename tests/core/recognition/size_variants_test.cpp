// Size families found in a base (size_variants.hpp): one mesh at several sizes, or hulls that
// are scaled copies under other names; not sizes too near to tell apart, nor other shapes.
#include "core/recognition/size_variants.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

// A part whose hull is a box of the given half extents, its diameter the box's diagonal.
ModelPart box_part(const std::string& name, const std::string& mesh,
                   const Eigen::Vector3d& half_mm) {
  ModelPart part;
  part.name = name;
  part.mesh = mesh;
  for (int corner = 0; corner < 8; ++corner)
    part.hull_vertices_mm.emplace_back((corner & 1 ? 1 : -1) * half_mm.x(),
                                       (corner & 2 ? 1 : -1) * half_mm.y(),
                                       (corner & 4 ? 1 : -1) * half_mm.z());
  part.diameter_mm = 2 * half_mm.norm();
  return part;
}

TEST(SizeVariants, ScaledHullsAreOneShapeAndOtherProportionsAreNot) {
  const ModelPart a = box_part("a", "a.off", {30, 20, 10});
  EXPECT_TRUE(same_shape_scaled(a, box_part("b", "b.off", {33, 22, 11}), 1e-3));
  EXPECT_TRUE(same_shape_scaled(a, a, 1e-3));
  EXPECT_FALSE(same_shape_scaled(a, box_part("c", "c.off", {33, 22, 10}), 1e-3));
  ModelPart fewer = a;
  fewer.hull_vertices_mm.pop_back();
  EXPECT_FALSE(same_shape_scaled(a, fewer, 1e-3));
}

TEST(SizeVariants, FamiliesByMeshOrHullAndOnlySizesFarEnoughApart) {
  ModelBase base;
  base.parts = {
      box_part("block", "block.off", {30, 20, 10}),
      box_part("block-110", "block.off", {33, 22, 11}),
      box_part("block-renamed", "other.off", {36.3, 24.2, 12.1}),     // a scaled copy
      box_part("block-copy", "block.off", {30.1, 20.0667, 10.0333}),  // 0.3 % larger
      box_part("plate", "plate.off", {30, 20, 2}),
  };
  // The gear's case: one mesh whose hulls differ in a corner still makes one family.
  base.parts.push_back(box_part("gear", "gear.off", {20, 20, 5}));
  base.parts.push_back(box_part("gear-121", "gear.off", {24.2, 24.2, 6.05}));
  base.parts.back().hull_vertices_mm.pop_back();
  const std::vector<std::vector<int>> variants = find_size_variants(base, SizeVariantParameters{});
  ASSERT_EQ(variants.size(), base.parts.size());
  EXPECT_EQ(variants[0], (std::vector<int>{1, 2}));
  EXPECT_EQ(variants[1], (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(variants[2], (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(variants[3], (std::vector<int>{1, 2}));
  EXPECT_TRUE(variants[4].empty());
  EXPECT_EQ(variants[5], (std::vector<int>{6}));
  EXPECT_EQ(variants[6], (std::vector<int>{5}));
}

TEST(SizeVariants, ScaledStartsCarryTheSceneCentroidWhereTheScaleMovesIt) {
  // A scene seen on a part 10 % smaller: its centroid at (10, 0, 5) in that part's frame,
  // the scene frame turned 90 degrees about z from the part's.
  RigidTransform T_part_scene;
  T_part_scene.rotation = rotation_from_xyz_angles_deg(0, 0, 90);
  const Eigen::Vector3d centroid_in_scene_mm(4, -7, 2);
  T_part_scene.translation_mm =
      Eigen::Vector3d(10, 0, 5) - T_part_scene.rotation * centroid_in_scene_mm;
  const std::vector<RigidTransform> starts =
      scaled_size_starts(std::span(&T_part_scene, 1), 1.1, centroid_in_scene_mm);
  ASSERT_EQ(starts.size(), 2u);
  EXPECT_TRUE(starts[0].rotation.isApprox(T_part_scene.rotation));
  EXPECT_NEAR((starts[0].apply(centroid_in_scene_mm) - Eigen::Vector3d(11, 0, 5.5)).norm(), 0,
              1e-9);
  EXPECT_TRUE(starts[1].rotation.isApprox(T_part_scene.rotation));
  EXPECT_NEAR((starts[1].translation_mm - T_part_scene.translation_mm).norm(), 0, 1e-12);
  EXPECT_TRUE(scaled_size_starts({}, 1.1, centroid_in_scene_mm).empty());
}

}  // namespace
}  // namespace cosmos
