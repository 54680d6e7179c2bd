#include "firmware_bridge/profile_resampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/profile.hpp"

namespace cosmos {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

struct Points {
  std::vector<float> x_mm;
  std::vector<float> z_mm;
  void add(double x, double z) {
    x_mm.push_back(static_cast<float>(x));
    z_mm.push_back(static_cast<float>(z));
  }
};

Profile grid(double x0_mm, double dx_mm, std::size_t width) {
  Profile p;
  p.x0_mm = x0_mm;
  p.dx_mm = dx_mm;
  p.resize(width);
  return p;
}

// Least-squares slope and intercept of the profile's valid samples.
void fit_line(const Profile& p, double& slope, double& intercept) {
  double n = 0, sx = 0, sz = 0, sxx = 0, sxz = 0;
  for (std::size_t i = 0; i < p.width(); ++i) {
    if (!p.has_data(i)) continue;
    const double x = p.x_mm(i);
    n += 1;
    sx += x;
    sz += p.z_mm[i];
    sxx += x * x;
    sxz += x * p.z_mm[i];
  }
  slope = (n * sxz - sx * sz) / (n * sxx - sx * sx);
  intercept = (sz - slope * sx) / n;
}

// Irregular point spacing (as perspective gives) on a tilted plane z = 10 + 0.5 x.
TEST(ProfileResampling, TiltedLineLandsAtTheRightHeightAndSlope) {
  Points pts;
  for (int i = 0; i < 500; ++i) {
    const double x = -50.0 + 0.2 * i + 0.07 * std::sin(1.3 * i);
    pts.add(x, 10.0 + 0.5 * x);
  }
  Profile p = grid(-40.0, 0.5, 160);  // −40 … +39.5 mm, inside the points' −50 … +49.8
  EXPECT_EQ(resample_to_profile(pts.x_mm, pts.z_mm, {}, p), 160);
  double worst = 0.0;
  for (std::size_t i = 0; i < p.width(); ++i)
    worst = std::max(worst, std::abs(p.z_mm[i] - (10.0 + 0.5 * p.x_mm(i))));
  EXPECT_LE(worst, 1e-4);
  double slope = 0, intercept = 0;
  fit_line(p, slope, intercept);
  EXPECT_NEAR(slope, 0.5, 1e-6);
  EXPECT_NEAR(intercept, 10.0, 1e-4);
}

TEST(ProfileResampling, SamplesBeyondThePointsStayEmpty) {
  Points pts;
  for (int i = 0; i <= 50; ++i) pts.add(0.2 * i, 5.0);  // 0 … 10 mm
  Profile p = grid(-5.0, 0.5, 40);                      // −5 … 14.5 mm
  EXPECT_EQ(resample_to_profile(pts.x_mm, pts.z_mm, {}, p), 21);
  EXPECT_FALSE(p.has_data(9));        // x = −0.5
  EXPECT_FLOAT_EQ(p.z_mm[10], 5.0f);  // x = 0, on the first point
  EXPECT_FLOAT_EQ(p.z_mm[30], 5.0f);  // x = 10, on the last point
  EXPECT_FALSE(p.has_data(31));
}

// A box 20 mm tall on the belt: belt at z = 0 for x < 0, box top at z = 20 for x ≥ 0.
// Nothing may be interpolated down the box's side.
TEST(ProfileResampling, NoInterpolationAcrossADepthJump) {
  Points pts;
  for (int i = 0; i < 100; ++i) {
    const double x = -10.0 + 0.2 * i + 0.05;  // −9.95 … 9.85; no point at the edge
    pts.add(x, x < 0.0 ? 0.0 : 20.0);
  }
  Profile p = grid(-10.0, 0.1, 200);
  resample_to_profile(pts.x_mm, pts.z_mm, {}, p);
  // The last belt point is x = −0.15, the first box point x = 0.05: samples −0.1 and 0.0
  // lie between them.
  EXPECT_FLOAT_EQ(p.z_mm[98], 0.0f);    // x = −0.2
  EXPECT_FALSE(p.has_data(99));         // x = −0.1
  EXPECT_FALSE(p.has_data(100));        // x = 0.0
  EXPECT_FLOAT_EQ(p.z_mm[101], 20.0f);  // x = 0.1
  // With a jump limit above the box height its side counts as a steep surface, and is joined.
  ProfileResamplingParameters tolerant;
  tolerant.max_z_jump_mm = 25.0;
  resample_to_profile(pts.x_mm, pts.z_mm, tolerant, p);
  EXPECT_NEAR(p.z_mm[99], 0.05 / 0.2 * 20.0, 1e-4);
  EXPECT_NEAR(p.z_mm[100], 0.15 / 0.2 * 20.0, 1e-4);
}

TEST(ProfileResampling, NoInterpolationAcrossAGapButAcrossAMissingColumn) {
  Points pts;
  for (int i = 0; i <= 100; ++i) {
    const double x = 0.2 * i;
    const bool occluded = x > 8.1 && x < 11.9;  // 8 … 12 mm: a 4 mm gap (> 3·dx = 1.5 mm)
    const bool dropout = i == 80;               // one missing column: 0.4 mm gap
    pts.add(occluded || dropout ? kNaN : x, occluded || dropout ? kNaN : 3.0 + 0.1 * x);
  }
  Profile p = grid(0.0, 0.5, 41);  // 0 … 20 mm
  resample_to_profile(pts.x_mm, pts.z_mm, {}, p);
  EXPECT_NEAR(p.z_mm[16], 3.8f, 1e-5);  // x = 8.0
  for (std::size_t i = 17; i <= 23; ++i) EXPECT_FALSE(p.has_data(i)) << "x = " << p.x_mm(i);
  EXPECT_NEAR(p.z_mm[24], 4.2f, 1e-5);  // x = 12.0
  EXPECT_NEAR(p.z_mm[32], 4.6f, 1e-5);  // x = 16.0, where column 80 dropped out
  EXPECT_TRUE(p.has_data(40));
}

TEST(ProfileResampling, IsolatedPointSetsItsNearestSampleOnly) {
  Points pts;
  pts.add(kNaN, kNaN);
  pts.add(4.1, 7.0);  // 0.1 mm from sample 8 (x = 4.0)
  pts.add(kNaN, kNaN);
  pts.add(9.0, 1.0);  // far from the first: not joined
  Profile p = grid(0.0, 0.5, 30);
  EXPECT_EQ(resample_to_profile(pts.x_mm, pts.z_mm, {}, p), 2);
  EXPECT_FLOAT_EQ(p.z_mm[8], 7.0f);
  EXPECT_FLOAT_EQ(p.z_mm[18], 1.0f);
}

// Where the stripe folds back in x (a concave corner seen at an angle), the higher surface
// is kept: it is the one a scanner looking down sees.
TEST(ProfileResampling, OverlappingSegmentsKeepTheHigherSurface) {
  Points pts;
  pts.add(0.0, 1.0);
  pts.add(2.0, 1.0);
  pts.add(1.0, 2.0);  // folds back 1 mm, 1 mm higher
  pts.add(3.0, 2.0);
  Profile p = grid(0.0, 0.25, 13);
  ProfileResamplingParameters wide_gaps;
  wide_gaps.max_gap_in_dx = 10.0;
  resample_to_profile(pts.x_mm, pts.z_mm, wide_gaps, p);
  EXPECT_FLOAT_EQ(p.z_mm[2], 1.0f);   // x = 0.5: only the lower segment
  EXPECT_FLOAT_EQ(p.z_mm[6], 2.0f);   // x = 1.5: under both, the higher wins
  EXPECT_FLOAT_EQ(p.z_mm[12], 2.0f);  // x = 3.0
}

TEST(Profile, ResizeMarksNoDataAndKeepsItsCapacity) {
  Profile p;
  p.reserve(2048);
  const float* storage = p.z_mm.data();
  p.resize(1280);
  for (std::size_t i = 0; i < p.width(); ++i) ASSERT_FALSE(p.has_data(i));
  p.z_mm[3] = 1.0f;
  p.resize(600);
  p.resize(2048);
  EXPECT_FALSE(p.has_data(3));
  EXPECT_EQ(p.z_mm.data(), storage);
  EXPECT_EQ(p.z_mm.capacity(), 2048u);
  p.x0_mm = -128.0;
  p.dx_mm = 0.2;
  EXPECT_DOUBLE_EQ(p.x_mm(10), -126.0);
}

}  // namespace
}  // namespace cosmos
