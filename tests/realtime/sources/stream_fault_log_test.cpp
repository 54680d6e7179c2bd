// Which parts a recorded stream fault touches, by the sequence numbers of the part's rows
// (its first row, its last row with data, the last row added to it), and a log that has
// wrapped past a part.
#include "realtime/sources/stream_fault_log.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace cosmos {
namespace {

TEST(StreamFaultLog, AnEncoderFaultTouchesThePartsRowsAfterTheFirstUpToItsLastWithData) {
  auto log = std::make_unique<StreamFaultLog>();
  log->record(StreamFaultKind::kEncoderJump, 99, 100);
  EXPECT_EQ(log->fault_in({90, 105, 110}), StreamFaultKind::kEncoderJump);  // inside
  EXPECT_EQ(log->fault_in({80, 100, 110}),
            StreamFaultKind::kEncoderJump);  // at the row whose count the pose carries
  // After its data, in the empty rows the tracker waited through: neither its rows nor its
  // pose's count moved.
  EXPECT_EQ(log->fault_in({80, 95, 100}), StreamFaultKind::kNone);
  EXPECT_EQ(log->fault_in({100, 105, 110}),
            StreamFaultKind::kNone);                                  // its first row
  EXPECT_EQ(log->fault_in({80, 95, 99}), StreamFaultKind::kNone);     // ended before it
  EXPECT_EQ(log->fault_in({101, 120, 125}), StreamFaultKind::kNone);  // began after it
}

TEST(StreamFaultLog, LostFramesTouchOnlyThePartWhoseDataTheyAreAmongOrBeside) {
  auto log = std::make_unique<StreamFaultLog>();
  log->record(StreamFaultKind::kSequenceGap, 99, 105);  // frames 100 to 104 lost
  EXPECT_EQ(log->fault_in({90, 102, 110}), StreamFaultKind::kSequenceGap);   // among its rows
  EXPECT_EQ(log->fault_in({90, 99, 110}), StreamFaultKind::kSequenceGap);    // right after it
  EXPECT_EQ(log->fault_in({105, 120, 125}), StreamFaultKind::kSequenceGap);  // right before
  // In the empty rows a part keeps until the tracker completes it: nothing of it was lost.
  EXPECT_EQ(log->fault_in({80, 98, 110}), StreamFaultKind::kNone);
  EXPECT_EQ(log->fault_in({106, 120, 125}), StreamFaultKind::kNone);
  // A loss the source reported without a gap in seq lies between the two profiles.
  log->record(StreamFaultKind::kSequenceGap, 199, 200);
  EXPECT_EQ(log->fault_in({200, 220, 230}), StreamFaultKind::kSequenceGap);
  EXPECT_EQ(log->fault_in({201, 220, 230}), StreamFaultKind::kNone);
}

TEST(StreamFaultLog, LaserOffAlsoTouchesThePartsNeighbours) {
  auto log = std::make_unique<StreamFaultLog>();
  log->record(StreamFaultKind::kLaserOff, 99, 100);
  EXPECT_EQ(log->fault_in({80, 99, 110}), StreamFaultKind::kLaserOff);    // ended right before
  EXPECT_EQ(log->fault_in({101, 110, 115}), StreamFaultKind::kLaserOff);  // began right after
  EXPECT_EQ(log->fault_in({102, 110, 115}), StreamFaultKind::kNone);
  EXPECT_EQ(log->fault_in({80, 98, 110}), StreamFaultKind::kNone);
}

TEST(StreamFaultLog, APartOlderThanTheLogIsUnchecked) {
  auto log = std::make_unique<StreamFaultLog>();
  for (std::uint64_t k = 0; k < StreamFaultLog::kCapacity + 10; ++k)
    log->record(StreamFaultKind::kLaserOff, 999 + k, 1000 + k);
  EXPECT_EQ(log->fault_in({5, 6, 7}), StreamFaultKind::kUnchecked);
  EXPECT_EQ(log->fault_in({900'000, 900'010, 900'020}), StreamFaultKind::kNone);
  log->clear();
  EXPECT_EQ(log->fault_in({5, 1 << 30, 1 << 30}), StreamFaultKind::kNone);
}

}  // namespace
}  // namespace cosmos
