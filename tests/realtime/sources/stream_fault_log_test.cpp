// Which parts a recorded stream fault touches, and a log that has wrapped past a part.
#include "realtime/sources/stream_fault_log.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace cosmos {
namespace {

TEST(StreamFaultLog, AFaultTouchesThePartsRowsAfterTheFirst) {
  auto log = std::make_unique<StreamFaultLog>();
  log->record(StreamFaultKind::kEncoderJump, 100, 39'600, 40'000);
  EXPECT_EQ(log->fault_in(90, 42'000), StreamFaultKind::kEncoderJump);  // inside
  EXPECT_EQ(log->fault_in(100, 42'000),
            StreamFaultKind::kNone);  // its first row: positioned by the last
  EXPECT_EQ(log->fault_in(90, 39'600), StreamFaultKind::kNone);   // ended before it
  EXPECT_EQ(log->fault_in(101, 50'000), StreamFaultKind::kNone);  // began after it
}

TEST(StreamFaultLog, LaserOffAlsoTouchesThePartsNeighbours) {
  auto log = std::make_unique<StreamFaultLog>();
  log->record(StreamFaultKind::kLaserOff, 100, 39'600, 40'000);
  EXPECT_EQ(log->fault_in(80, 39'600), StreamFaultKind::kLaserOff);   // ended right before
  EXPECT_EQ(log->fault_in(101, 45'000), StreamFaultKind::kLaserOff);  // began right after
  EXPECT_EQ(log->fault_in(102, 45'000), StreamFaultKind::kNone);
  EXPECT_EQ(log->fault_in(80, 39'200), StreamFaultKind::kNone);
}

TEST(StreamFaultLog, APartOlderThanTheLogIsUnchecked) {
  auto log = std::make_unique<StreamFaultLog>();
  for (std::uint64_t k = 0; k < StreamFaultLog::kCapacity + 10; ++k)
    log->record(StreamFaultKind::kLaserOff, 1000 + k, 0, 0);
  EXPECT_EQ(log->fault_in(5, -1), StreamFaultKind::kUnchecked);
  EXPECT_EQ(log->fault_in(900'000, 1), StreamFaultKind::kNone);
  log->clear();
  EXPECT_EQ(log->fault_in(5, 1 << 30), StreamFaultKind::kNone);
}

}  // namespace
}  // namespace cosmos
