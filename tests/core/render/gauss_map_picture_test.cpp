// gauss_map.png: the Gauss patch map (§3.2.2, Fig. 3.12), each CSMP a disc at its orientation
// G0 (Eq. 3.7) seen from +z, disc area proportional to patch area, on the hand-made view
// (hand_made_view.hpp) and on one-patch views.
#include "core/render/gauss_map_picture.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/render/shape_category_palette.hpp"
#include "tests/core/hand_made_view.hpp"
#include "tests/core/render/picture_probe.hpp"

namespace cosmos::testing {
namespace {

constexpr int kCentre = kGaussMapSizePx / 2;
constexpr BgrColor kWhite = rgb(255, 255, 255);

TEST(GaussMapPicture, PlacesDiscsAtTheirNormals) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_gauss_map_picture(analysis.view);
  ASSERT_EQ(picture.width(), kGaussMapSizePx);
  ASSERT_EQ(picture.height(), kGaussMapSizePx);
  // Patch 0 faces the sensor (+z): its disc, the largest (radius 0.14 R = 35 px), is centred.
  EXPECT_EQ(picture(kCentre, kCentre), patch_color(0));
  EXPECT_EQ(picture(kCentre, kCentre - 28), patch_color(0));
  EXPECT_EQ(picture(kCentre, kCentre + 28), patch_color(0));
  EXPECT_NE(picture(kCentre, kCentre - 40), patch_color(0));
  // Patch 1 faces +x by 0.6: 0.6 R to the right of the centre.
  const Eigen::Vector2d right = gauss_map_position_px({0.6, 0, 0.8});
  EXPECT_DOUBLE_EQ(right.x(), kCentre + 0.6 * kGaussMapRadiusPx);
  EXPECT_EQ(picture(static_cast<int>(right.x()), static_cast<int>(right.y())), patch_color(1));
  // Patch 2 faces -y: above the centre (+y is drawn downwards).
  EXPECT_EQ(picture(kCentre, kCentre - 150), patch_color(2));
  EXPECT_EQ(picture(4, kCentre), kWhite);
}

TEST(GaussMapPicture, PositionIsTheOrthographicProjectionOfTheNormal) {
  EXPECT_EQ(gauss_map_position_px({0, 0, 1}), Eigen::Vector2d(320, 320));
  EXPECT_EQ(gauss_map_position_px({0, 0, -1}), Eigen::Vector2d(320, 320));
  EXPECT_EQ(gauss_map_position_px({1, 0, 0}), Eigen::Vector2d(320 + kGaussMapRadiusPx, 320));
  EXPECT_EQ(gauss_map_position_px({0, -0.6, 0.8}), Eigen::Vector2d(320, 320 - 150));
  EXPECT_EQ(gauss_map_position_px({-0.6, 0, 0.8}), Eigen::Vector2d(320 - 150, 320));
}

// Disc area ~ patch area: patch 3 (6 mm^2 against the largest 8 mm^2) gets radius
// 35 sqrt(6 / 8) = 30.3 px around (170, 320).
TEST(GaussMapPicture, DiscAreaFollowsThePatchArea) {
  const BgrPicture picture = render_gauss_map_picture(hand_made_view_analysis().view);
  const Eigen::Vector2d at = gauss_map_position_px({-0.6, 0, 0.8});
  const int x = static_cast<int>(at.x()), y = static_cast<int>(at.y());
  EXPECT_EQ(picture(x, y), patch_color(3));
  EXPECT_EQ(picture(x, y - 27), patch_color(3));
  EXPECT_EQ(picture(x, y + 27), patch_color(3));
  EXPECT_NE(picture(x, y - 34), patch_color(3));
  EXPECT_NE(picture(x, y + 34), patch_color(3));
}

// One patch, at a normal whose disc centre lies on no graticule line: filled when it faces the
// sensor, a ring when it faces away (the far hemisphere).
TEST(GaussMapPicture, PatchesFacingAwayAreDrawnHollow) {
  CosmosView view;
  view.patches = {hand_patch(7, 5.0, 0.5, {0.36, 0.48, 0.8}, 20, {})};
  const Eigen::Vector2d at = gauss_map_position_px({0.36, 0.48, 0.8});
  ASSERT_EQ(at, Eigen::Vector2d(320 + 90, 320 + 120));
  const BgrPicture near_side = render_gauss_map_picture(view);
  EXPECT_EQ(near_side(410, 440), patch_color(7));
  view.patches[0].mean_normal = {0.36, 0.48, -0.8};
  const BgrPicture far_side = render_gauss_map_picture(view);
  EXPECT_EQ(far_side(410, 440), kWhite);
  // Inside radius 30 the near disc is all patch colour (but for its label, which sits
  // outside), the far one has none; the far ring darkens the 33-37 px annulus beyond what the
  // graticule alone does there.
  const BgrPicture graticule = render_gauss_map_picture(CosmosView{});
  int near_inside = 0, far_inside = 0, inside = 0, far_ring = 0, graticule_ring = 0;
  for (int dy = -40; dy <= 40; ++dy)
    for (int dx = -40; dx <= 40; ++dx) {
      const double r = std::hypot(dx, dy);
      const int x = 410 + dx, y = 440 + dy;
      if (r < 30) {
        ++inside;
        near_inside += near_side(x, y) == patch_color(7);
        far_inside += far_side(x, y) == patch_color(7);
      } else if (r >= 33 && r <= 37) {
        far_ring += far_side(x, y) != kWhite;
        graticule_ring += graticule(x, y) != kWhite;
      }
    }
  EXPECT_EQ(near_inside, inside);
  EXPECT_EQ(far_inside, 0);
  EXPECT_GT(far_ring, graticule_ring + 400);
}

TEST(GaussMapPicture, AnEmptyViewIsTheGraticuleAlone) {
  const BgrPicture picture = render_gauss_map_picture(CosmosView{});
  ASSERT_EQ(picture.width(), kGaussMapSizePx);
  // Inside the sphere between the graticule lines: background; the rim circle: grey ink.
  EXPECT_EQ(picture(410, 440), kWhite);
  int rim_pixels = 0;
  for (int dx = -4; dx <= 4; ++dx)
    rim_pixels += picture(kCentre + kGaussMapRadiusPx + dx, kCentre - 1) != kWhite;
  EXPECT_GE(rim_pixels, 2);
}

}  // namespace
}  // namespace cosmos::testing
