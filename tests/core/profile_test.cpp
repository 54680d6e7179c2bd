// Profile (core/profile.hpp): one laser line's heights. A slot reused by the real-time ring
// must come back with no stale data and without reallocating.
#include "core/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cosmos {
namespace {

TEST(Profile, SamplesLieAlongTheLaserLine) {
  Profile profile;
  EXPECT_DOUBLE_EQ(profile.x_mm(3), 3.0);  // x0 0, dx 1 by default
  profile.x0_mm = -10.0;
  profile.dx_mm = 0.25;
  EXPECT_DOUBLE_EQ(profile.x_mm(0), -10.0);
  EXPECT_DOUBLE_EQ(profile.x_mm(8), -8.0);
  EXPECT_DOUBLE_EQ(profile.x_mm(100), 15.0);
}

TEST(Profile, ResizeMarksEverySampleAsNoData) {
  EXPECT_TRUE(std::isnan(Profile::kNoData));
  Profile profile;
  profile.resize(5);
  ASSERT_EQ(profile.width(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_FALSE(profile.has_data(i)) << i;
  profile.z_mm[2] = 1.25f;
  profile.z_mm[4] = 0.0f;
  EXPECT_TRUE(profile.has_data(2));
  EXPECT_TRUE(profile.has_data(4));
  EXPECT_FALSE(profile.has_data(3));
  // The same slot for the next, narrower line: the old heights are gone.
  profile.resize(3);
  ASSERT_EQ(profile.width(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_FALSE(profile.has_data(i)) << i;
  profile.z_mm[1] = 7.0f;
  profile.clear_data();
  EXPECT_FALSE(profile.has_data(1));
  EXPECT_EQ(profile.width(), 3u);
}

TEST(Profile, ReservedWidthIsNeverReallocated) {
  Profile profile;
  profile.reserve(640);
  const float* storage = profile.z_mm.data();
  for (std::size_t width : {640u, 100u, 1u, 640u, 333u}) {
    profile.resize(width);
    EXPECT_EQ(profile.z_mm.data(), storage) << width;
    EXPECT_EQ(profile.width(), width);
  }
}

}  // namespace
}  // namespace cosmos
