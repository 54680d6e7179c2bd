// spectrum.png: the shape spectrum (§3.2.3) as bars over S_I in [0, 1] in their Fig. 3.3
// category colours, and the planar fraction as its own bar, on the hand-made view's spectrum
// (hand_made_view.hpp: 36.4 % at S_I 0.97, 18.2 % at 0.50, 27.3 % at 0.03, 18.2 % planar).
#include "core/render/spectrum_picture.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/render/shape_category_palette.hpp"
#include "tests/core/hand_made_view.hpp"
#include "tests/core/render/picture_probe.hpp"

namespace cosmos::testing {
namespace {

constexpr BgrColor kWhite = rgb(255, 255, 255);

TEST(SpectrumPicture, HasBarsInCategoryColoursAndAPlanarBar) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_spectrum_picture(analysis.spectrum, analysis.moments);
  EXPECT_EQ(picture.width(), kSpectrumWidthPx);
  EXPECT_EQ(picture.height(), kSpectrumHeightPx);
  // The tallest bin (36 % of the area, S_I 0.97) fills a column of the plot in cap colour; the
  // dome name under the axis is the only dome-coloured ink.
  EXPECT_GT(count_color(picture, kShapeCategoryTable[8].color), 550);  // ~318 px high, 2-3 wide
  EXPECT_GT(count_color(picture, kShapeCategoryTable[0].color), 400);  // ~239 px high
  EXPECT_LT(count_color(picture, kShapeCategoryTable[7].color), 200);
  EXPECT_GT(count_color(picture, kPlanarColor), 1500);  // 18 % on a 350 px axis, 50 px wide
}

// The plot spans x 80..800 for S_I 0..1 and y 440 (0) up to 90 (the axis top). The largest bin,
// 36.4 %, puts the axis top at the next round tick, 40 %: a bin of p % reaches
// y = 440 - round(p / 40 * 350). Bin [0.97, 0.975) starts at x = 80 + round(0.97 * 720) = 778.
TEST(SpectrumPicture, BarsStandAtTheirShapeIndexAndReachTheirShare) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_spectrum_picture(analysis.spectrum, analysis.moments);
  struct Bar {
    int x;         // a column inside the bar
    double share;  // of the visible area
    BgrColor color;
  };
  const Bar bars[] = {{779, 8.0 / 22, kShapeCategoryTable[8].color},   // S_I 0.97: cap
                      {441, 4.0 / 22, kShapeCategoryTable[4].color},   // S_I 0.50: saddle
                      {103, 6.0 / 22, kShapeCategoryTable[0].color}};  // S_I 0.03: cup
  for (const Bar& bar : bars) {
    const int top = 440 - static_cast<int>(std::lround(100 * bar.share / 40 * 350));
    EXPECT_EQ(picture(bar.x, top + 4), bar.color) << bar.x;
    EXPECT_EQ(picture(bar.x, 430), bar.color) << bar.x;
    EXPECT_EQ(picture(bar.x, top - 6), kWhite) << bar.x;
  }
  // Between the bars the plot is empty.
  EXPECT_EQ(picture(600, 300), kWhite);
  // The planar bar, x 900..950 on its own 0-100 % axis: 18.2 % reaches y = 440 - 64 = 376.
  EXPECT_EQ(picture(925, 400), kPlanarColor);
  EXPECT_EQ(picture(925, 340), kWhite);
}

// Planar-grey pixels inside the planar bar's frame (x 900..950, y 90..440).
int planar_bar_pixels(const BgrPicture& picture) {
  int count = 0;
  for (int y = 91; y < 440; ++y)
    for (int x = 901; x < 950; ++x) count += picture(x, y) == kPlanarColor ? 1 : 0;
  return count;
}

TEST(SpectrumPicture, PlanarBarHeightIsThePlanarFraction) {
  ViewAnalysis analysis = hand_made_view_analysis();
  analysis.spectrum.planar_fraction = 0.0;
  EXPECT_EQ(planar_bar_pixels(render_spectrum_picture(analysis.spectrum, analysis.moments)), 0);
  analysis.spectrum.planar_fraction = 1.0;  // the whole axis: 349 rows inside the frame
  EXPECT_EQ(planar_bar_pixels(render_spectrum_picture(analysis.spectrum, analysis.moments)),
            49 * 349);
  analysis.spectrum.planar_fraction = 0.5;  // from y = 440 - 175 = 265 down
  EXPECT_EQ(planar_bar_pixels(render_spectrum_picture(analysis.spectrum, analysis.moments)),
            49 * (440 - 266));
}

}  // namespace
}  // namespace cosmos::testing
