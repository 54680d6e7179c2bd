// The belt's rows (belt_contact.hpp) for a block 10 x 20 x 30 mm in known poses: the lowest
// corner's height when it floats, every sunken corner when it sinks, their shares of the
// weight, and the row's signed distance measured as a registration measures a scene point's.
#include "core/registration/belt_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/rigid_transform.hpp"

namespace cosmos {
namespace {

std::vector<Eigen::Vector3d> block_corners_mm() {
  std::vector<Eigen::Vector3d> corners;
  for (const double x : {0.0, 10.0})
    for (const double y : {0.0, 20.0})
      for (const double z : {0.0, 30.0}) corners.emplace_back(x, y, z);
  return corners;
}

struct CollectedRow {
  BeltRow row;
  double share;
};

std::vector<CollectedRow> rows_of(const BeltContact& belt, const RigidTransform& T_model_scene) {
  std::vector<CollectedRow> rows;
  for_each_belt_row(belt, T_model_scene, [&](const BeltRow& row, double share) {
    rows.push_back({row, share});
  });
  return rows;
}

TEST(BeltContact, AFloatingPartGetsOneRowAtItsLowestCorner) {
  const std::vector<Eigen::Vector3d> corners = block_corners_mm();
  const BeltContact belt{corners, RigidTransform::identity(), 1.0};
  // The scene's origin 2.5 mm below the part's, turned a little about x and y: the belt lies
  // under the bottom face, 1.8-2.5 mm below its corners.
  const Eigen::Matrix3d tilt = rotation_from_vector(Eigen::Vector3d(0.02, -0.03, 0.0));
  const RigidTransform T_model_scene{tilt, Eigen::Vector3d(0.0, 0.0, -2.5)};
  const std::vector<CollectedRow> rows = rows_of(belt, T_model_scene);
  ASSERT_EQ(rows.size(), 1u);
  const Eigen::Vector3d normal = tilt.col(2);
  double lowest_mm = 1e9;
  Eigen::Vector3d lowest_corner_mm = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& corner : corners) {
    const double height_mm = normal.dot(corner - T_model_scene.translation_mm);
    if (height_mm < lowest_mm) {
      lowest_mm = height_mm;
      lowest_corner_mm = corner;
    }
  }
  EXPECT_NEAR(rows[0].row.height_mm, lowest_mm, 1e-12);
  EXPECT_NEAR(rows[0].row.height_mm, 1.8, 0.05);
  EXPECT_DOUBLE_EQ(rows[0].share, 1.0);
  // The row's point lies on the belt under that corner, and its signed distance from the
  // model's plane through the corner (normal -n) is the corner's height, as d_s is a scene
  // point's.
  EXPECT_NEAR(normal.dot(rows[0].row.point_mm - T_model_scene.translation_mm), 0.0, 1e-12);
  EXPECT_TRUE(rows[0].row.normal.isApprox(-normal));
  EXPECT_NEAR(rows[0].row.normal.dot(rows[0].row.point_mm - lowest_corner_mm), lowest_mm, 1e-12);
}

TEST(BeltContact, ASunkenPartGetsARowAtEveryCornerBelowTheBeltSharingTheWeight) {
  const std::vector<Eigen::Vector3d> corners = block_corners_mm();
  const BeltContact belt{corners, RigidTransform::identity(), 1.0};
  // Level, 1.5 mm into the belt: the four bottom corners are below it, the top ones 28.5 mm
  // above.
  const RigidTransform T_model_scene{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 1.5)};
  const std::vector<CollectedRow> rows = rows_of(belt, T_model_scene);
  ASSERT_EQ(rows.size(), 4u);
  for (const CollectedRow& r : rows) {
    EXPECT_NEAR(r.row.height_mm, -1.5, 1e-12);
    EXPECT_DOUBLE_EQ(r.share, 0.25);
    EXPECT_NEAR(r.row.point_mm.z(), 1.5, 1e-12);
  }
}

TEST(BeltContact, TheViewsFrameMovesTheCornersAndNoCornersOrNoWeightHoldNothing) {
  const std::vector<Eigen::Vector3d> corners = block_corners_mm();
  // The model is a view of the part turned upside down and raised 30 mm: the part's top face is
  // at the view's bottom, which lies on the belt when T_model_scene is the identity.
  const RigidTransform T_model_part{Eigen::Vector3d(1, -1, -1).asDiagonal().toDenseMatrix(),
                                    Eigen::Vector3d(0, 20, 30)};
  const BeltContact belt{corners, T_model_part, 1.0};
  const std::vector<CollectedRow> rows = rows_of(belt, RigidTransform::identity());
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].row.height_mm, 0.0);
  EXPECT_EQ(rows[0].row.point_mm.z(), 0.0);
  EXPECT_TRUE(belt.holds());
  EXPECT_FALSE((BeltContact{{}, RigidTransform::identity(), 1.0}).holds());
  EXPECT_FALSE((BeltContact{corners, RigidTransform::identity(), 0.0}).holds());
}

}  // namespace
}  // namespace cosmos
