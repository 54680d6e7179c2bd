// The table of every adjacent CSMP pair of every model view (patch_pair_table.hpp): both
// orders of each pair, filed under its key, each entry the pair's frame in its part's frame,
// whichever view it came from.
#include "core/indexing/patch_pair_table.hpp"

#include <gtest/gtest.h>

#include "core/rigid_transform.hpp"
#include "tests/core/indexing/patch_object.hpp"

namespace cosmos {
namespace {

RigidTransform pose(double rx_deg, double ry_deg, double rz_deg, Eigen::Vector3d t_mm) {
  return {rotation_from_xyz_angles_deg(rx_deg, ry_deg, rz_deg), t_mm};
}

TEST(PatchPairTable, FilesBothOrdersOfEveryAdjacentPairUnderItsKeyInThePartFrame) {
  ModelBase base;
  base.parts.resize(2);
  base.views.push_back(
      testing::object_model_view(testing::block_patches(), 0, pose(10, 20, 30, {1, 2, 300})));
  base.views.push_back(
      testing::object_model_view(testing::block_patches(), 0, pose(-40, 5, 100, {-3, 0, 280})));
  base.views.push_back(
      testing::object_model_view(testing::round_patches(), 1, pose(0, 0, 0, {0, 0, 250})));
  PatchPairKeyParameters parameters;
  parameters.adjacent_only = false;
  // Every two patches: 10 of the block's 5, 6 of the round part's 4; both orders, every view.
  EXPECT_EQ(PatchPairTable(base, parameters).size(), 2u * (10 + 10 + 6));
  parameters.adjacent_only = true;
  const PatchPairTable table(base, parameters);
  // The block has 8 adjacent pairs, the round part 5.
  EXPECT_EQ(table.size(), 2u * (8 + 8 + 5));

  // Pair (1, 2) of the block from its first view: under its key, with its frame in the part
  // frame, and the same pair of the second view beside it at the same part-frame pose.
  const ModelBaseView& view = base.views[0];
  const std::optional<PatchPairFeature> feature =
      patch_pair_feature(view.cosmos.patches[1], view.cosmos.patches[2], parameters);
  ASSERT_TRUE(feature);
  const RigidTransform T_part_pair = view.T_scanner_part.inverse() * feature->T_view_pair;
  int found = 0;
  for (const IndexedPatchPair& entry : table.entries(patch_pair_key(*feature, parameters))) {
    if (entry.part != 0) continue;
    const Eigen::Matrix3d rotation = entry.q_part_pair.toRotationMatrix().cast<double>();
    if ((rotation - T_part_pair.rotation).norm() < 1e-5 &&
        (entry.t_part_pair_mm.cast<double>() - T_part_pair.translation_mm).norm() < 1e-3)
      ++found;
  }
  EXPECT_EQ(found, 2);
  std::size_t filed = 0;
  for (int key = 0; key < parameters.key_count(); ++key) filed += table.entries(key).size();
  EXPECT_EQ(filed, table.size());
}

TEST(PatchPairTable, AnEmptyBaseHasAnEmptyTable) {
  const PatchPairTable table(ModelBase{}, PatchPairKeyParameters{});
  EXPECT_EQ(table.size(), 0u);
  EXPECT_TRUE(table.entries(0).empty());
}

}  // namespace
}  // namespace cosmos
