#pragma once
// What the web view shows, kept by the web side: the last CellStatus, the recent parts (pose
// and belt tile) and the pose-latency histogram. The publisher thread hands in what it has
// already (the status it sends each period, each pose after it went out); the server's
// threads take copies. One mutex, owned here, guards it all, and the publisher holds it only
// to swap in what it rendered beforehand (a part's JSON and tile are made outside the lock),
// so a slow browser never holds up the publisher; the acquisition thread never comes here.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "realtime/cell/cell_status.hpp"
#include "realtime/cell/part_recognition.hpp"
#include "realtime/config/web_view_settings.hpp"
#include "realtime/web/belt_tile.hpp"
#include "realtime/web/latency_bins.hpp"

namespace cosmos {

// One part, rendered once on the publisher thread.
struct WebPart {
  std::uint64_t index = 0;  // the store's running number, from 1
  std::int64_t last_profile = -1;
  nlohmann::ordered_json pose;  // pose_json
  std::string event_json;       // {"pose": ..., "tile": ...}: the page's `part` event
};

// How far a reader has got: what it saw last.
struct WebCursor {
  std::uint64_t summary_version = 0;  // status, histogram, geometry
  std::uint64_t part_index = 0;
};

struct WebUpdate {
  WebCursor cursor;                                   // pass back to the next wait_for_update
  std::string summary_json;                           // status_document()'s; empty when unchanged
  std::vector<std::shared_ptr<const WebPart>> parts;  // new since the cursor, oldest first
  bool closed = false;
};

class WebSnapshotStore {
 public:
  explicit WebSnapshotStore(const WebViewSettings& settings);

  // The cell's side: the app before the run, then the publisher thread.
  void set_geometry(const BeltStripGeometry& geometry);
  void update_status(const CellStatus& status);
  void add_part(const PartRecognition& recognition);
  // No more updates: waiting readers return at once (the server is going down).
  void close();

  // The server's side. Waits until there is something newer than `seen`, the timeout passes
  // or the store closes.
  WebUpdate wait_for_update(const WebCursor& seen, std::chrono::milliseconds timeout) const;
  // /api/status: {"status": status_json or null, "pose_latency_ms": LatencyBins::json(),
  // "belt": the strip's geometry and head profile, "recent_poses": rows of the table}.
  std::string status_document() const;
  std::string poses_document() const;  // /api/poses: {"poses": [newest first]}

 private:
  struct Summary {
    bool has_status = false;
    CellStatus status;
    LatencyBins latency;
    BeltStripGeometry geometry;
    std::int64_t head_profile = -1;
  };
  static std::string summary_json(const Summary& summary, const WebViewSettings& settings);
  void trim_locked();

  const WebViewSettings settings_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  Summary summary_;
  std::uint64_t summary_version_ = 1;  // a new reader (cursor 0) gets the summary at once
  std::deque<std::shared_ptr<const WebPart>> parts_;
  std::uint64_t next_part_index_ = 1;
  bool closed_ = false;
};

}  // namespace cosmos
