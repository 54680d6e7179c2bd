#pragma once
// A Publisher in front of the cell's own: everything goes on to it unchanged, and each
// CellStatus the publisher thread sends is also handed to the web view's store. The web view
// thus sees the very status the robot gets, at the same period, with no hook in the cell's
// threads.
#include "realtime/lcm/pose_publisher.hpp"
#include "realtime/web/web_snapshot_store.hpp"

namespace cosmos {

class StatusTeePublisher final : public Publisher {
 public:
  StatusTeePublisher(Publisher& next, WebSnapshotStore& store) : next_(next), store_(store) {}

  bool publish(const PartPose& pose) override { return next_.publish(pose); }
  bool publish(const CellStatus& status) override;
  bool publish(const Profile& profile) override { return next_.publish(profile); }

 private:
  Publisher& next_;
  WebSnapshotStore& store_;
};

}  // namespace cosmos
