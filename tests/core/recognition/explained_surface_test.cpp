// The pixels a recognized part explains: those on its surface under its pose, and the
// interior of what remains once its fringe is taken away.
#include "core/recognition/explained_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cosmos {
namespace {

// A 20 x 20 mm square in the part frame's z = 0 plane, every 0.5 mm.
PartDistanceField square_part() {
  std::vector<Eigen::Vector3d> points;
  for (double x = -10; x <= 10; x += 0.5)
    for (double y = -10; y <= 10; y += 0.5) points.emplace_back(x, y, 0);
  return PartDistanceField(points, PartDistanceFieldParameters{0.5, 6.0});
}

TEST(ExplainedSurface, PixelsOnThePlacedPartAreExplainedAndOthersNot) {
  RangeImage scene(100, 40, 0.5, 0.5);  // x 0 .. 49.5, y 0 .. 19.5
  for (int row = 0; row < 40; ++row)
    for (int column = 0; column < 100; ++column)
      // The square at 5 mm height over x 0 .. 20; another part, 12 mm high, beyond x = 30.
      if (column <= 40)
        scene.z_mm(column, row) = 5.0f;
      else if (column >= 60)
        scene.z_mm(column, row) = 12.0f;
  const RigidTransform T_scene_part{Eigen::Matrix3d::Identity(), Eigen::Vector3d(10, 10, 5)};
  const std::vector<std::uint8_t> explained =
      explained_pixels(scene, square_part(), T_scene_part, 1.0);
  int on_square = 0, on_other = 0;
  for (int row = 0; row < 40; ++row)
    for (int column = 0; column < 100; ++column) {
      const bool is = explained[static_cast<std::size_t>(row) * 100 + column] != 0;
      (column <= 40 ? on_square : on_other) += is ? 1 : 0;
    }
  EXPECT_EQ(on_square, 41 * 40);
  EXPECT_EQ(on_other, 0);
  // Lifted by 3 mm the same pose explains nothing within 1 mm.
  const RigidTransform lifted{Eigen::Matrix3d::Identity(), Eigen::Vector3d(10, 10, 8)};
  const std::vector<std::uint8_t> none = explained_pixels(scene, square_part(), lifted, 1.0);
  EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
}

TEST(ExplainedSurface, FootprintHoldsWhatLiesOverOrUnderThePartAndNothingBeside) {
  // The square stood on its edge (its plane vertical, across x): seen from above it is a
  // 20 mm line, yet its footprint is the line's pixels at every height, and only those.
  RangeImage scene(100, 40, 0.5, 0.5);  // x 0 .. 49.5, y 0 .. 19.5
  std::vector<std::uint8_t> pixels(100 * 40, 0);
  for (int row = 0; row < 40; ++row)
    for (int column = 0; column < 100; ++column) {
      // Every pixel holds a point: 30 mm up where the part's top edge is seen, 2 mm (a
      // neighbour's low surface) elsewhere.
      scene.z_mm(column, row) = column == 20 ? 30.0f : 2.0f;
      pixels[static_cast<std::size_t>(row) * 100 + column] = 1;
    }
  // Part frame x along scene y, part y down scene z: the square spans z 0 .. 20 at x = 10.
  Eigen::Matrix3d R_scene_part;
  R_scene_part << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  const RigidTransform T_scene_part{R_scene_part, Eigen::Vector3d(10, 10, 10)};
  const double distance_mm = 1.0;
  const std::vector<std::uint8_t> under =
      footprint_pixels(scene, pixels, square_part(), T_scene_part, 30.0, distance_mm);
  int inside = 0, beside = 0;
  for (int row = 0; row < 40; ++row)
    for (int column = 0; column < 100; ++column) {
      if (!under[static_cast<std::size_t>(row) * 100 + column]) continue;
      const double x_mm = scene.x_mm(column);
      const double y_mm = scene.y_mm(row);
      // Within distance_mm of the square's line x = 10, y 0 .. 20 (one voxel's slack).
      const bool near = std::abs(x_mm - 10) <= distance_mm + 0.5 && y_mm <= 20.5;
      (near ? inside : beside) += 1;
    }
  EXPECT_EQ(beside, 0);
  EXPECT_GE(inside, 5 * 40);  // x 9 .. 11 at least, on every row
  // Only the pixels asked about are looked at.
  const std::vector<std::uint8_t> none = footprint_pixels(
      scene, std::vector<std::uint8_t>(100 * 40, 0), square_part(), T_scene_part, 30.0, 1.0);
  EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
}

TEST(ExplainedSurface, InteriorPixelsLeaveOutTheFringe) {
  std::vector<std::uint8_t> mask(10 * 6, 0);
  for (int row = 1; row < 5; ++row)
    for (int column = 2; column < 8; ++column)
      mask[static_cast<std::size_t>(row) * 10 + column] = 1;
  EXPECT_EQ(interior_pixels(mask, 10, 6), 2 * 4);  // a 4 x 6 block: its inner 2 x 4
  mask[0] = 1;                                     // a lone pixel has no interior
  EXPECT_EQ(interior_pixels(mask, 10, 6), 8);
}

}  // namespace
}  // namespace cosmos
