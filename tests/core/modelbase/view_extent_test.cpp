// A view's extent (view_extent.hpp): a box's height and widths across seen straight along an
// axis and over a cell about it, tilted toward its long side; the start views' cell radius on the
// six axes; and which of a base's views get one.
#include "core/modelbase/view_extent.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/modelbase/model_base.hpp"

namespace cosmos {
namespace {

// 100 x 40 x 20 mm, centred.
std::vector<Eigen::Vector3d> box_hull() {
  std::vector<Eigen::Vector3d> corners;
  for (int corner = 0; corner < 8; ++corner)
    corners.emplace_back(corner & 1 ? 50 : -50, corner & 2 ? 20 : -20, corner & 4 ? 10 : -10);
  return corners;
}

double degrees(double rad) { return rad * 180 / M_PI; }

TEST(ViewExtent, SeenAlongAnAxisABoxIsItsSideTallAndItsFaceWide) {
  const ViewExtent extent = view_extent(box_hull(), Eigen::Vector3d::UnitZ(), 0);
  EXPECT_NEAR(extent.highest_mm, 20, 1e-9);
  // The widest width across a 100 x 40 face is its diagonal, the narrowest its short side.
  EXPECT_NEAR(extent.widest_mm, std::sqrt(100.0 * 100 + 40 * 40), 0.1);
  EXPECT_NEAR(extent.narrowest_mm, 40, 1e-9);
}

TEST(ViewExtent, OverACellTheGreatestOfEachIsTaken) {
  const double radius_rad = 10 * M_PI / 180;
  const ViewExtent extent = view_extent(box_hull(), Eigen::Vector3d::UnitZ(), radius_rad);
  // Tilted 10 degrees toward the face's diagonal, the box stands tallest: 20 cos + 107.7 sin.
  const double tilted_height_mm =
      20 * std::cos(radius_rad) + std::sqrt(100.0 * 100 + 40 * 40) * std::sin(radius_rad);
  EXPECT_LE(extent.highest_mm, tilted_height_mm + 1e-9);
  EXPECT_GE(extent.highest_mm, tilted_height_mm - 1.0);
  // Tilted toward the short side, the narrowest width across grows to 40 cos + 20 sin.
  EXPECT_GE(extent.narrowest_mm, 40 * std::cos(radius_rad) + 20 * std::sin(radius_rad) - 1.0);
  EXPECT_GE(extent.widest_mm, std::sqrt(100.0 * 100 + 40 * 40) - 0.1);
  EXPECT_LE(extent.widest_mm, std::sqrt(100.0 * 100 + 40 * 40 + 20 * 20) + 1e-9);
}

TEST(ViewExtent, WithoutAHullEveryFigureIsUnbounded) {
  const ViewExtent extent = view_extent({}, Eigen::Vector3d::UnitZ(), 0.2);
  EXPECT_TRUE(std::isinf(extent.highest_mm));
  EXPECT_TRUE(std::isinf(extent.widest_mm));
  EXPECT_TRUE(std::isinf(extent.narrowest_mm));
}

TEST(ViewExtent, TheSixAxesLeaveTheOctantsCentresFarthest) {
  std::vector<Eigen::Vector3d> axes;
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {1.0, -1.0}) axes.push_back(sign * Eigen::Vector3d::Unit(axis));
  const double octant_centre_deg = degrees(std::acos(1 / std::sqrt(3.0)));
  EXPECT_GE(degrees(covering_radius_rad(axes)), octant_centre_deg);
  EXPECT_LE(degrees(covering_radius_rad(axes)), octant_centre_deg + 2);
  EXPECT_NEAR(degrees(covering_radius_rad({})), 180, 1e-9);
}

TEST(ViewExtent, OnlyTheStartViewsWithPointsAreBounded) {
  ModelBase base;
  base.parts.resize(2);
  base.parts[0].hull_vertices_mm = box_hull();
  base.parts[1].hull_vertices_mm = box_hull();
  const auto add_view = [&](int part, int view_index, const Eigen::Vector3d& direction,
                            bool measured) {
    ModelBaseView& view = base.views.emplace_back();
    view.part_index = part;
    view.view_index = view_index;
    view.direction_part = direction;
    if (measured) view.registration.position_mm = Eigen::Matrix3Xd::Zero(3, 5);
  };
  add_view(0, 3, Eigen::Vector3d::UnitZ(), true);    // a coarse view
  add_view(0, 7, -Eigen::Vector3d::UnitZ(), true);   // a coarse view
  add_view(0, 2, Eigen::Vector3d::UnitX(), true);    // a finer one
  add_view(0, 11, Eigen::Vector3d::UnitY(), false);  // coarse, but nothing measured
  add_view(1, 3, Eigen::Vector3d::UnitZ(), true);
  summarize_view_extents(base, 0);
  EXPECT_FALSE(std::isinf(base.views[0].extent.highest_mm));
  EXPECT_FALSE(std::isinf(base.views[1].extent.highest_mm));
  EXPECT_TRUE(std::isinf(base.views[2].extent.highest_mm));
  EXPECT_TRUE(std::isinf(base.views[3].extent.highest_mm));
  EXPECT_TRUE(std::isinf(base.views[4].extent.highest_mm));  // the other part's, not summarized
  // Two opposite start views leave every direction within 90 degrees of one: the cell holds
  // the box's diagonal, along which it stands tallest.
  EXPECT_NEAR(base.views[0].extent.highest_mm, std::sqrt(100.0 * 100 + 40 * 40 + 20 * 20), 1.0);
}

}  // namespace
}  // namespace cosmos
