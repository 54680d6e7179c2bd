// The publisher in front of the cell's own: every message goes on unchanged, and each status
// also reaches the web view's store.
#include "realtime/web/status_tee_publisher.hpp"

#include <gtest/gtest.h>

#include "realtime/lcm/memory_publisher.hpp"

namespace cosmos {
namespace {

TEST(StatusTeePublisher, PassesEverythingOnAndKeepsTheStatus) {
  MemoryPublisher next;
  WebSnapshotStore store{WebViewSettings{}};
  StatusTeePublisher tee(next, store);

  PartPose pose;
  pose.part_name = "cow";
  EXPECT_TRUE(tee.publish(pose));
  Profile profile;
  profile.seq = 42;
  EXPECT_TRUE(tee.publish(profile));
  CellStatus status;
  status.state = CellState::kScanning;
  status.profiles_dropped = 17;
  EXPECT_TRUE(tee.publish(status));

  ASSERT_EQ(next.poses.size(), 1u);
  EXPECT_EQ(next.poses[0].part_name, "cow");
  ASSERT_EQ(next.profiles.size(), 1u);
  EXPECT_EQ(next.profiles[0].seq, 42u);
  ASSERT_EQ(next.statuses.size(), 1u);
  EXPECT_EQ(next.statuses[0].profiles_dropped, 17);

  const auto document = nlohmann::json::parse(store.status_document());
  EXPECT_EQ(document.at("status").at("state"), "SCANNING");
  EXPECT_EQ(document.at("status").at("profiles_dropped"), 17);
  // Poses reach the store through the cell's pose observer, with their part's profiles.
  EXPECT_EQ(nlohmann::json::parse(store.poses_document()).at("poses").size(), 0u);
}

}  // namespace
}  // namespace cosmos
