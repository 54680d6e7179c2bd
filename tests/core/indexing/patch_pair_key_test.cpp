// The key of an adjacent CSMP pair (§3.2, §5.3): the same under any rigid motion of the scene,
// with the pair's frame moving along; planar patches in a bin of their own; small, far or
// degenerate pairs not keyed; and the neighbouring bins a scene pair also looks up.
#include "core/indexing/patch_pair_key.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace cosmos {
namespace {

Csmp patch(int id, double shape_index, bool planar, Eigen::Vector3d normal,
           Eigen::Vector3d centroid_mm, double area_mm2 = 100.0) {
  Csmp p;
  p.id = id;
  p.shape_index = shape_index;
  p.planar = planar;
  p.mean_normal = normal.normalized();
  p.centroid_mm = centroid_mm;
  p.area_mm2 = area_mm2;
  return p;
}

Csmp moved(const Csmp& p, const RigidTransform& T) {
  Csmp q = p;
  q.mean_normal = T.rotate(p.mean_normal);
  q.centroid_mm = T.apply(p.centroid_mm);
  return q;
}

RigidTransform random_motion(std::mt19937_64& random) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> offset(-200.0, 200.0);
  const Eigen::Quaterniond q(normal(random), normal(random), normal(random), normal(random));
  return {q.normalized().toRotationMatrix(),
          Eigen::Vector3d(offset(random), offset(random), offset(random))};
}

TEST(PatchPairKey, TheKeyIsTheSameAfterAnyRigidMotionAndTheFrameMovesWithThePatches) {
  const PatchPairKeyParameters parameters;
  // A cylinder-like ridge beside a tilted flat face, 23 mm apart.
  const Csmp a = patch(0, 0.52, false, {0.1, 0.2, 1.0}, {10.0, 4.0, 50.0});
  const Csmp b = patch(1, 2.0, true, {0.7, -0.1, 0.7}, {30.0, 12.0, 44.0});
  const std::optional<PatchPairFeature> original = patch_pair_feature(a, b, parameters);
  ASSERT_TRUE(original);
  std::array<int, kMaxNearbyPatchPairKeys> original_keys{};
  const int original_count = nearby_patch_pair_keys(*original, parameters, original_keys);
  std::mt19937_64 random(17);
  for (int trial = 0; trial < 50; ++trial) {
    const RigidTransform T = random_motion(random);
    const std::optional<PatchPairFeature> motion =
        patch_pair_feature(moved(a, T), moved(b, T), parameters);
    ASSERT_TRUE(motion);
    EXPECT_EQ(patch_pair_key(*motion, parameters), patch_pair_key(*original, parameters));
    EXPECT_NEAR(motion->angle, original->angle, 1e-9);
    EXPECT_NEAR(motion->distance, original->distance, 1e-9);
    std::array<int, kMaxNearbyPatchPairKeys> keys{};
    ASSERT_EQ(nearby_patch_pair_keys(*motion, parameters, keys), original_count);
    EXPECT_TRUE(std::equal(keys.begin(), keys.begin() + original_count, original_keys.begin()));
    // T_moved_pair = T * T_view_pair: the pose between the two frames is the motion itself.
    const RigidTransform expected = T * original->T_view_pair;
    EXPECT_LT((motion->T_view_pair.rotation - expected.rotation).norm(), 1e-9);
    EXPECT_LT((motion->T_view_pair.translation_mm - expected.translation_mm).norm(), 1e-9);
  }
}

PatchPairKeyParameters fine_bins() {
  PatchPairKeyParameters parameters;
  parameters.shape_index_bins = 8;
  parameters.normal_angle_bin_deg = 15.0;
  parameters.centroid_distance_bin_mm = 6.0;
  parameters.centroid_distance_bins = 40;
  return parameters;
}

TEST(PatchPairKey, BinsTheShapeIndexTheNormalsAngleAndTheCentroidsDistance) {
  const PatchPairKeyParameters parameters = fine_bins();
  const Csmp a = patch(0, -0.9, false, {0, 0, 1}, {0, 0, 0});
  const Csmp b = patch(1, 0.0, true, {0, 1, 1}, {0, 20, 0});  // 45 deg, 20 mm
  const std::optional<PatchPairFeature> feature = patch_pair_feature(a, b, parameters);
  ASSERT_TRUE(feature);
  EXPECT_NEAR(feature->shape_a, 0.4, 1e-12);  // (S_I + 1) / 2 x 8
  EXPECT_EQ(feature->shape_b, 8.0);           // the planar bin
  EXPECT_NEAR(feature->angle, 3.0, 1e-9);
  EXPECT_NEAR(feature->distance, 20.0 / 6.0, 1e-12);
  const int angle_bins = 12, distance_bins = 40, shape_bins = 9;
  EXPECT_EQ(parameters.angle_bins(), angle_bins);
  EXPECT_EQ(parameters.key_count(), shape_bins * shape_bins * angle_bins * distance_bins);
  EXPECT_EQ(patch_pair_key(*feature, parameters),
            ((0 * shape_bins + 8) * angle_bins + 3) * distance_bins + 3);
  // The frame: origin the midpoint, x the first normal, y towards the second centroid.
  EXPECT_LT((feature->T_view_pair.translation_mm - Eigen::Vector3d(0, 10, 0)).norm(), 1e-12);
  EXPECT_LT((feature->T_view_pair.rotation.col(0) - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  EXPECT_LT((feature->T_view_pair.rotation.col(1) - Eigen::Vector3d::UnitY()).norm(), 1e-12);
  EXPECT_NEAR(feature->T_view_pair.rotation.determinant(), 1.0, 1e-12);
}

TEST(PatchPairKey, SmallFarOrStackedPairsHaveNoKey) {
  const PatchPairKeyParameters parameters = fine_bins();
  const Csmp a = patch(0, 0.5, false, {0, 0, 1}, {0, 0, 0});
  EXPECT_FALSE(patch_pair_feature(a, patch(1, 0.5, false, {1, 0, 0}, {10, 0, 0}, 5.0),
                                  parameters));  // 5 mm^2: too small
  EXPECT_FALSE(patch_pair_feature(a, patch(1, 0.5, false, {1, 0, 0}, {250, 0, 0}),
                                  parameters));  // 250 mm: beyond 40 bins of 6 mm
  EXPECT_FALSE(patch_pair_feature(a, patch(1, 0.5, false, {1, 0, 0}, {0.5, 0, 10}),
                                  parameters));  // along a's normal: no lateral offset
}

TEST(PatchPairKey, AScenePairAlsoLooksUpTheNearerNeighbouringBins) {
  const PatchPairKeyParameters parameters = fine_bins();
  // Curved, curved: every coordinate has a nearer neighbour, 2^4 keys.
  const Csmp a = patch(0, 0.1, false, {0, 0, 1}, {0, 0, 0});     // shape 4.4: bins 4, 3
  const Csmp b = patch(1, 0.7, false, {0, 1, 1}, {0, 16.5, 0});  // 6.8: bins 6, 7
  const std::optional<PatchPairFeature> curved = patch_pair_feature(a, b, parameters);
  ASSERT_TRUE(curved);
  std::array<int, kMaxNearbyPatchPairKeys> keys{};
  ASSERT_EQ(nearby_patch_pair_keys(*curved, parameters, keys), 16);
  EXPECT_EQ(keys[0], patch_pair_key(*curved, parameters));
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());  // all distinct
  // A planar patch has no neighbouring shape bin, and a curved one in the last curved bin
  // never looks into the planar one: 1 x 1 x 2 x 2.
  const Csmp top = patch(0, 0.99, false, {0, 0, 1}, {0, 0, 0});  // shape 7.96: bin 7 only
  const Csmp flat = patch(1, 2.0, true, {0, 1, 1}, {0, 16.5, 0});
  const std::optional<PatchPairFeature> mixed = patch_pair_feature(top, flat, parameters);
  ASSERT_TRUE(mixed);
  std::array<int, kMaxNearbyPatchPairKeys> mixed_keys{};
  ASSERT_EQ(nearby_patch_pair_keys(*mixed, parameters, mixed_keys), 4);
  const int planar_bin = parameters.shape_index_bins;
  const int per_shape_a =
      parameters.shape_bins() * parameters.angle_bins() * parameters.centroid_distance_bins;
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(mixed_keys[static_cast<std::size_t>(k)] / per_shape_a, planar_bin - 1);
}

}  // namespace
}  // namespace cosmos
