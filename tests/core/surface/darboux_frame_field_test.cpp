// Darboux frame fields (core/surface/darboux_frame_field.hpp): the neutral frame of a new
// field, the neighbour numbering the same-side masks use, and principal curvatures of a 3D
// Weingarten tensor W = k1 e1 e1^T + k2 e2 e2^T built by hand on a tilted tangent plane.
#include "core/surface/darboux_frame_field.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <set>
#include <utility>

namespace cosmos {
namespace {

// The frame of normal n with principal curvatures k1 along e1 and k2 along n x e1.
FrameValues frame_of(const Eigen::Vector3d& n, const Eigen::Vector3d& e1, double k1, double k2) {
  const Eigen::Vector3d e2 = n.cross(e1);
  const Eigen::Matrix3d W = k1 * e1 * e1.transpose() + k2 * e2 * e2.transpose();
  return {static_cast<float>(n.x()),   static_cast<float>(n.y()),   static_cast<float>(n.z()),
          static_cast<float>(W(0, 0)), static_cast<float>(W(0, 1)), static_cast<float>(W(0, 2)),
          static_cast<float>(W(1, 1)), static_cast<float>(W(1, 2)), static_cast<float>(W(2, 2))};
}

// A normal tilted 35 degrees from z, and a tangent direction turned 40 degrees within its
// tangent plane away from the projected x axis.
struct TiltedPlane {
  Eigen::Vector3d n;
  Eigen::Vector3d e1;
};
TiltedPlane tilted_plane() {
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(0.6109, Eigen::Vector3d(1, 2, 0).normalized()).toRotationMatrix();
  const Eigen::Vector3d n = tilt * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d e1 = Eigen::AngleAxisd(0.698, n) * (tilt * Eigen::Vector3d::UnitX());
  return {n, e1};
}

TEST(DarbouxFrameField, NewFieldIsInvalidWithTheNeutralFrame) {
  const DarbouxFrameField field(5, 3);
  EXPECT_EQ(field.width(), 5);
  EXPECT_EQ(field.height(), 3);
  for (std::size_t i = 0; i < 15; ++i) {
    EXPECT_EQ(field.valid[i], 0);
    EXPECT_EQ(field.same_side[i], 0);
    const FrameValues f = frame_at(field, i);
    for (int c = 0; c < kFrameComponents; ++c) EXPECT_EQ(f[c], c == kNz ? 1.0f : 0.0f) << c;
    for (const auto& grid : field.position_mm) EXPECT_EQ(grid[i], 0.0f);
  }
}

TEST(DarbouxFrameField, NeighbourBitsPairEachDirectionWithItsOpposite) {
  // The forward half (bits 4..7) are the opposites of bits 3..0: scanning only the forward
  // half visits every 8-adjacent pair once (cosmos_view.cpp relies on it).
  std::set<std::pair<int, int>> offsets;
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(kNeighborOffsets[7 - k].column, -kNeighborOffsets[k].column) << k;
    EXPECT_EQ(kNeighborOffsets[7 - k].row, -kNeighborOffsets[k].row) << k;
    EXPECT_LE(std::abs(kNeighborOffsets[k].column), 1);
    EXPECT_LE(std::abs(kNeighborOffsets[k].row), 1);
    offsets.insert({kNeighborOffsets[k].column, kNeighborOffsets[k].row});
  }
  EXPECT_EQ(offsets.size(), 8u);
  EXPECT_EQ(offsets.count({0, 0}), 0u);
  // Raster order: the row above first, the right neighbour is bit 4.
  EXPECT_EQ(kNeighborOffsets[0].row, -1);
  EXPECT_EQ(kNeighborOffsets[4].column, 1);
  EXPECT_EQ(kNeighborOffsets[4].row, 0);
}

TEST(DarbouxFrameField, PrincipalCurvaturesOfAHandMadeTensorOnATiltedPlane) {
  const TiltedPlane plane = tilted_plane();
  ASSERT_NEAR(plane.n.dot(plane.e1), 0.0, 1e-12);
  // Given in either order, kappa1 is the larger and direction1 its direction.
  for (const auto& [k_e1, k_e2] : {std::pair{0.05, -0.02}, std::pair{-0.02, 0.05}}) {
    const PrincipalCurvatures k = principal_curvatures(frame_of(plane.n, plane.e1, k_e1, k_e2));
    EXPECT_NEAR(k.kappa1, 0.05, 1e-6);
    EXPECT_NEAR(k.kappa2, -0.02, 1e-6);
    const Eigen::Vector3d d1(k.direction1[0], k.direction1[1], k.direction1[2]);
    const Eigen::Vector3d expected = k_e1 > k_e2 ? plane.e1 : plane.n.cross(plane.e1);
    EXPECT_NEAR(d1.norm(), 1.0, 1e-6);
    EXPECT_NEAR(std::abs(d1.dot(expected)), 1.0, 1e-6);
    EXPECT_NEAR(d1.dot(plane.n), 0.0, 1e-6);  // tangent
  }
}

TEST(DarbouxFrameField, PrincipalValuesAgreeWithTheDecomposition) {
  const TiltedPlane plane = tilted_plane();
  for (const auto& [k1, k2] :
       {std::pair{0.04, 0.04}, std::pair{0.0, -0.08}, std::pair{0.3, 0.1}, std::pair{0.0, 0.0}}) {
    const FrameValues f = frame_of(plane.n, plane.e1, k1, k2);
    float kappa1 = 0, kappa2 = 0;
    principal_values(f, kappa1, kappa2);
    // At an umbilic the discriminant is a float cancellation, and its square root magnifies it.
    const double tolerance = k1 == k2 ? 5e-5 : 2e-6;
    EXPECT_NEAR(kappa1, std::max(k1, k2), tolerance) << k1 << "," << k2;
    EXPECT_NEAR(kappa2, std::min(k1, k2), tolerance) << k1 << "," << k2;
  }
}

TEST(DarbouxFrameField, PixelAccessReadsThatPixelsNineComponents) {
  DarbouxFrameField field(4, 2);
  const TiltedPlane plane = tilted_plane();
  const FrameValues f = frame_of(plane.n, plane.e1, 0.07, 0.01);
  const std::size_t pixel = field.valid.index(2, 1);
  for (int c = 0; c < kFrameComponents; ++c) field.frame[c][pixel] = f[c];
  EXPECT_EQ(frame_at(field, pixel), f);
  const PrincipalCurvatures k = principal_curvatures(field, pixel);
  EXPECT_NEAR(k.kappa1, 0.07, 1e-6);
  EXPECT_NEAR(k.kappa2, 0.01, 1e-6);
  EXPECT_EQ(principal_curvatures(field, field.valid.index(1, 1)).kappa1, 0.0f);  // still neutral
}

}  // namespace
}  // namespace cosmos
