// A view's metric signature (view_signature.hpp): unchanged as its points turn about the viewing
// direction and slide across it, moved by exactly the distance its points are raised, apart from
// another size of the same shape, and taken over a base's views above the part's lowest point.
#include "core/modelbase/view_signature.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/modelbase/model_base.hpp"

namespace cosmos {
namespace {

// A 63 x 42 mm ramp rising from 1 to 30 mm along x, sampled every 2.1 mm (in grid order; no
// radius or span falls on a bin's edge, where rounding could move it to the next).
Eigen::Matrix3Xd ramp(double scale = 1.0) {
  Eigen::Matrix3Xd points(3, 30 * 20);
  for (int row = 0; row < 20; ++row)
    for (int column = 0; column < 30; ++column)
      points.col(row * 30 + column) =
          scale * Eigen::Vector3d(2.1 * column - 30.45, 2.1 * row - 19.95, 1 + column);
  return points;
}

TEST(ViewSignature, TurningAboutTheViewingDirectionOrSlidingAcrossItChangesNothing) {
  const Eigen::Matrix3Xd points = ramp();
  const ViewSignature signature = view_signature(points, 0.0);
  ASSERT_FALSE(signature.empty());
  EXPECT_TRUE(is_cumulative(signature));
  EXPECT_EQ(signature_distance_mm(signature, signature), 0.0);
  for (const double turn_deg : {17.0, 90.0, 133.0}) {
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(turn_deg * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3Xd moved = (turn * points).colwise() + Eigen::Vector3d(140, -75, 0);
    EXPECT_LT(signature_distance_mm(signature, view_signature(moved, 0.0)), 1e-3) << turn_deg;
  }
}

TEST(ViewSignature, RaisingThePointsMovesTheirHeightsByAsMuch) {
  const Eigen::Matrix3Xd points = ramp();
  const Eigen::Matrix3Xd raised = points.colwise() + Eigen::Vector3d(0, 0, 8);
  // Two bins up, every point: the height distribution's earth mover's distance is 8 mm and the
  // radius and span distributions are the same.
  EXPECT_NEAR(signature_distance_mm(view_signature(points, 0.0), view_signature(raised, 0.0)), 8.0,
              1e-3);
  // Heights are taken above the base height given.
  EXPECT_EQ(signature_distance_mm(view_signature(points, 0.0), view_signature(raised, 8.0)), 0.0);
}

TEST(ViewSignature, AnotherSizeOfTheSameShapeIsFarther) {
  const ViewSignature signature = view_signature(ramp(), 0.0);
  const double ten_percent_mm = signature_distance_mm(signature, view_signature(ramp(1.1), 0.0));
  const double twenty_percent_mm = signature_distance_mm(signature, view_signature(ramp(1.2), 0.0));
  // A tenth larger: heights, radii and spans all grow by a tenth of their means (16, 18 and
  // 26 mm or so), give or take a bin.
  EXPECT_GT(ten_percent_mm, 3.0);
  EXPECT_LT(ten_percent_mm, 10.0);
  EXPECT_GT(twenty_percent_mm, 1.5 * ten_percent_mm);
}

TEST(ViewSignature, WithoutPointsASignatureIsEmptyAndInfinitelyFar) {
  const ViewSignature empty = view_signature(Eigen::Matrix3Xd(3, 0), 0.0);
  EXPECT_TRUE(empty.empty());
  EXPECT_TRUE(is_cumulative(empty));
  EXPECT_TRUE(std::isinf(signature_distance_mm(empty, view_signature(ramp(), 0.0))));
  ViewSignature broken = view_signature(ramp(), 0.0);
  broken.cumulative[ViewSignature::kHeightBins + 3] = 0;  // the radii fall back
  EXPECT_FALSE(is_cumulative(broken));
}

TEST(ViewSignature, ABaseViewsHeightsAreTakenAboveThePartsLowestCorner) {
  ModelBase base;
  base.parts.resize(1);
  // The part reaches 12 mm below its control points' lowest (the scanner saw its top only).
  base.parts[0].hull_vertices_mm = {{0, 0, -11}, {10, 0, 40}, {0, 10, 40}};
  ModelBaseView view;
  view.T_scanner_part.translation_mm = {0, 0, -1};
  view.registration.position_mm = ramp();
  base.views.push_back(view);
  ModelBaseView pointless;
  base.views.push_back(pointless);
  summarize_view_signatures(base, 0);
  const Eigen::Matrix3Xd above_corner = ramp().colwise() + Eigen::Vector3d(0, 0, 12);
  EXPECT_EQ(signature_distance_mm(base.views[0].signature, view_signature(above_corner, 0.0)), 0.0);
  EXPECT_TRUE(base.views[1].signature.empty());
}

}  // namespace
}  // namespace cosmos
