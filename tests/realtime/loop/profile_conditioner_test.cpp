// Conditioning sensor profiles onto the COSMOS grid.
#include "realtime/loop/profile_conditioner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace cosmos {
namespace {

// A sensor profile across [-128, 128) mm: a 0.2-slope ramp between x = -40 and 40 mm standing
// 10 mm above a belt at z = 2 mm, elsewhere the belt.
Profile sensor_profile(int points) {
  Profile profile;
  profile.dx_mm = 256.0 / points;
  profile.x0_mm = -128.0 + 0.5 * profile.dx_mm;
  profile.resize(points);
  for (int i = 0; i < points; ++i) {
    const double x = profile.x_mm(i);
    profile.z_mm[i] = static_cast<float>(std::abs(x) < 40 ? 12.0 + 0.2 * x : 2.0);
  }
  return profile;
}

ConditioningParameters belt_at_2mm() {
  ConditioningParameters parameters;
  parameters.belt_height_mm = 2.0;
  return parameters;
}

void expect_ramp(const std::vector<float>& z, const ProfileConditioner& conditioner) {
  int part = 0, background = 0;
  for (int k = 0; k < conditioner.width(); ++k) {
    const double x = conditioner.x0_mm() + k * 0.4;
    if (std::abs(x) < 39) {
      ASSERT_FALSE(std::isnan(z[k])) << x;
      EXPECT_NEAR(z[k], 10.0 + 0.2 * x, 1e-3) << x;
      ++part;
    } else if (std::abs(x) > 41) {
      EXPECT_TRUE(std::isnan(z[k])) << x;  // the belt is background
      ++background;
    }
  }
  EXPECT_GT(part, 190);
  EXPECT_GT(background, 420);
}

TEST(ProfileConditioner, FineSensorIsBoxAveragedOntoTheGrid) {
  const ProfileConditioner conditioner(belt_at_2mm(), SurfaceFitParameters{});
  ASSERT_EQ(conditioner.width(), 640);
  std::vector<float> z(conditioner.width());
  conditioner.condition(sensor_profile(3200), z.data());
  expect_ramp(z, conditioner);
}

TEST(ProfileConditioner, CoarseSensorIsInterpolated) {
  const ProfileConditioner conditioner(belt_at_2mm(), SurfaceFitParameters{});
  std::vector<float> z(conditioner.width());
  conditioner.condition(sensor_profile(320), z.data());
  expect_ramp(z, conditioner);
}

TEST(ProfileConditioner, NeverInterpolatesAcrossAJumpOrAGap) {
  const ProfileConditioner conditioner(belt_at_2mm(), SurfaceFitParameters{});
  Profile profile = sensor_profile(320);  // 0.8 mm samples
  for (int i = 0; i < 320; ++i) profile.z_mm[i] = profile.x_mm(i) < 0 ? 10.0f : 20.0f;
  profile.z_mm[250] = Profile::kNoData;
  std::vector<float> z(conditioner.width());
  conditioner.condition(profile, z.data());
  for (int k = 0; k < conditioner.width(); ++k) {
    const float value = z[k];
    if (!std::isnan(value)) {
      EXPECT_TRUE(value == 8.0f || value == 18.0f) << k << " " << value;
    }
  }
  const double gap_x = profile.x_mm(250);
  const int k_gap = static_cast<int>(std::lround((gap_x + 128.0) / 0.4));
  EXPECT_TRUE(std::isnan(z[k_gap]));
}

TEST(ProfileConditioner, AProfileWithoutUsableSpacingOrOriginGivesNoData) {
  const ProfileConditioner conditioner(belt_at_2mm(), SurfaceFitParameters{});
  const double infinity = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double dx_mm : {0.0, 1e-300, -0.5, infinity, nan}) {
    Profile profile = sensor_profile(1280);
    profile.dx_mm = dx_mm;
    std::vector<float> z(static_cast<std::size_t>(conditioner.width()), 1.0F);
    EXPECT_FALSE(conditioner.condition(profile, z.data())) << dx_mm;
    EXPECT_EQ(std::count_if(z.begin(), z.end(), [](float v) { return !std::isnan(v); }), 0)
        << dx_mm;
  }
  for (const double x0_mm : {1e300, -infinity, nan}) {
    Profile profile = sensor_profile(64);
    profile.x0_mm = x0_mm;
    std::vector<float> z(static_cast<std::size_t>(conditioner.width()), 1.0F);
    EXPECT_FALSE(conditioner.condition(profile, z.data())) << x0_mm;
    EXPECT_EQ(std::count_if(z.begin(), z.end(), [](float v) { return !std::isnan(v); }), 0)
        << x0_mm;
  }
  // Finite but far: the sample indices exceed int; nothing falls on the grid.
  for (const bool fine : {true, false}) {
    Profile profile = sensor_profile(fine ? 1280 : 64);
    profile.x0_mm = 9e5;
    if (fine) profile.dx_mm = 1e-4;
    std::vector<float> z(static_cast<std::size_t>(conditioner.width()), 1.0F);
    EXPECT_TRUE(conditioner.condition(profile, z.data()));
    EXPECT_EQ(std::count_if(z.begin(), z.end(), [](float v) { return !std::isnan(v); }), 0);
  }
  std::vector<float> z(static_cast<std::size_t>(conditioner.width()));
  EXPECT_TRUE(conditioner.condition(sensor_profile(1280), z.data()));
  expect_ramp(z, conditioner);
}

// The jump is the COSMOS fit's: with a fit that takes a 10 mm step as one surface, the grid
// is interpolated across it too.
TEST(ProfileConditioner, TakesTheDepthJumpFromTheFit) {
  SurfaceFitParameters fit;
  fit.depth_jump_mm = 15.0;
  const ProfileConditioner conditioner(belt_at_2mm(), fit);
  Profile profile = sensor_profile(320);  // 0.8 mm samples, the step between two of them
  for (int i = 0; i < 320; ++i) profile.z_mm[i] = profile.x_mm(i) < 0 ? 10.0f : 20.0f;
  std::vector<float> z(conditioner.width());
  conditioner.condition(profile, z.data());
  int between = 0;
  for (int k = 0; k < conditioner.width(); ++k) between += z[k] > 8.5f && z[k] < 17.5f ? 1 : 0;
  EXPECT_EQ(between, 2);  // the grid points x = ±0.2 mm, between the samples at ±0.4 mm
}

}  // namespace
}  // namespace cosmos
