#include "firmware_bridge/photo_eye_debouncer.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace cosmos {
namespace {

constexpr std::int64_t kMs = 1'000'000;

PhotoEyeParameters filtering() {
  PhotoEyeParameters p;
  p.debounce_ns = 1 * kMs;
  p.min_on_ns = 5 * kMs;
  p.min_off_ns = 20 * kMs;
  return p;
}

TEST(PhotoEyeDebouncer, WithoutFilteringEveryEdgeIsAChange) {
  PhotoEyeDebouncer eye;
  eye.reset(false, 0);
  const PhotoEyeChange on = eye.on_edge(true, 100, 7);
  EXPECT_TRUE(on.changed);
  EXPECT_TRUE(on.present);
  EXPECT_EQ(on.t_ns, 100);
  EXPECT_EQ(on.tag, 7);
  const PhotoEyeChange off = eye.on_edge(false, 300, 9);
  EXPECT_TRUE(off.changed);
  EXPECT_FALSE(off.present);
  EXPECT_EQ(eye.counts().parts, 1u);
}

TEST(PhotoEyeDebouncer, BouncingArrivalIsOnePartStampedAtItsFirstEdge) {
  PhotoEyeDebouncer eye(filtering());
  eye.reset(false, 0);
  // The leading edge of a part bounces for 0.3 ms.
  EXPECT_FALSE(eye.on_edge(true, 100 * kMs, 1000).changed);
  EXPECT_FALSE(eye.on_edge(false, 100 * kMs + 100'000, 1001).changed);
  EXPECT_FALSE(eye.on_edge(true, 100 * kMs + 300'000, 1002).changed);
  EXPECT_FALSE(eye.advance_to(104 * kMs).changed);  // 4 ms: shorter than min_on
  EXPECT_FALSE(eye.present());
  const PhotoEyeChange arrival = eye.advance_to(105 * kMs);
  ASSERT_TRUE(arrival.changed);
  EXPECT_TRUE(arrival.present);
  EXPECT_EQ(arrival.t_ns, 100 * kMs);  // where the part's edge was, not when it was believed
  EXPECT_EQ(arrival.tag, 1000);
  EXPECT_EQ(eye.counts().bounces, 2u);
  EXPECT_FALSE(eye.advance_to(200 * kMs).changed);  // reported once

  // The trailing edge bounces too, then the belt stays clear.
  EXPECT_FALSE(eye.on_edge(false, 300 * kMs, 2000).changed);
  EXPECT_FALSE(eye.on_edge(true, 300 * kMs + 200'000, 2001).changed);
  EXPECT_FALSE(eye.on_edge(false, 300 * kMs + 400'000, 2002).changed);
  const PhotoEyeChange departure = eye.advance_to(321 * kMs);
  ASSERT_TRUE(departure.changed);
  EXPECT_FALSE(departure.present);
  EXPECT_EQ(departure.t_ns, 300 * kMs);
  EXPECT_EQ(departure.tag, 2000);
  EXPECT_EQ(eye.counts().parts, 1u);
}

TEST(PhotoEyeDebouncer, ShortInterruptionIsRejected) {
  PhotoEyeDebouncer eye(filtering());
  eye.reset(false, 0);
  eye.on_edge(true, 10 * kMs);
  eye.on_edge(false, 12 * kMs);  // 2 ms of dust
  EXPECT_FALSE(eye.advance_to(100 * kMs).changed);
  EXPECT_FALSE(eye.present());
  EXPECT_EQ(eye.counts().rejected_pulses, 1u);
  EXPECT_EQ(eye.counts().parts, 0u);
}

TEST(PhotoEyeDebouncer, HoleInAPartIsBridged) {
  PhotoEyeDebouncer eye(filtering());
  eye.reset(false, 0);
  eye.on_edge(true, 10 * kMs);
  ASSERT_TRUE(eye.advance_to(20 * kMs).present);
  eye.on_edge(false, 50 * kMs);  // the beam passes through a hole for 8 ms
  const PhotoEyeChange during = eye.on_edge(true, 58 * kMs);
  EXPECT_FALSE(during.changed);
  EXPECT_FALSE(eye.advance_to(150 * kMs).changed);
  EXPECT_TRUE(eye.present());
  EXPECT_EQ(eye.counts().bridged_gaps, 1u);
  // A pending change that has lasted long enough is reported by the next edge even without
  // advance_to.
  eye.on_edge(false, 200 * kMs);
  const PhotoEyeChange next_part = eye.on_edge(true, 400 * kMs);
  ASSERT_TRUE(next_part.changed);
  EXPECT_FALSE(next_part.present);
  EXPECT_EQ(next_part.t_ns, 200 * kMs);
}

TEST(PhotoEyeDebouncer, ResetStateIsNotAnArrival) {
  PhotoEyeDebouncer eye(filtering());
  eye.reset(true, 0);  // a part already in the beam at start-up
  EXPECT_TRUE(eye.present());
  EXPECT_FALSE(eye.advance_to(100 * kMs).changed);
  EXPECT_EQ(eye.counts().parts, 0u);
}

}  // namespace
}  // namespace cosmos
