#pragma once
// Part-present from the photo-eye line's edges. The beam flickers: contacts and cheap
// sensors bounce, dust or a falling chip crosses it for a moment, and a part with holes or
// dark patches lets it through for a moment. Three times, each filtering one of those:
//   debounce_ns  edges closer than this to the previous edge are bounce; a level is only
//                believed once the line has been quiet this long;
//   min_on_ns    a beam interruption shorter than this is not a part (rejected pulse);
//   min_off_ns   a gap shorter than this inside a part does not end it (bridged gap).
// A change is reported once it has lasted long enough, stamped with the time of the edge
// that began it (the first edge of its bounce burst), so the part tracker gets where the
// part's edge really was, not when the filter made up its mind. The caller's context at that
// edge (the encoder count) travels with it as the tag.
//
// Real-time: fixed state, no allocation, no exceptions.
#include <cstdint>

namespace cosmos {

struct PhotoEyeParameters {
  std::int64_t debounce_ns = 0;
  std::int64_t min_on_ns = 0;
  std::int64_t min_off_ns = 0;
};

struct PhotoEyeChange {
  bool changed = false;
  bool present = false;   // the new state
  std::int64_t t_ns = 0;  // when it began
  std::int64_t tag = 0;   // the caller's tag given with that edge
};

struct PhotoEyeCounts {
  std::uint64_t edges = 0;
  std::uint64_t bounces = 0;          // edges inside debounce_ns of the previous one
  std::uint64_t rejected_pulses = 0;  // interruptions shorter than min_on_ns
  std::uint64_t bridged_gaps = 0;     // gaps shorter than min_off_ns
  std::uint64_t parts = 0;            // reported part arrivals
};

class PhotoEyeDebouncer {
 public:
  explicit PhotoEyeDebouncer(const PhotoEyeParameters& parameters = {});

  // The beam state read when the line was requested: taken as settled, not as an arrival.
  void reset(bool present, std::int64_t t_ns) noexcept;

  // One edge (level = beam interrupted after it), in time order. Reports at most one change:
  // a pending one that lasted long enough before this edge, or this edge itself when every
  // time is zero.
  PhotoEyeChange on_edge(bool level, std::int64_t t_ns, std::int64_t tag = 0) noexcept;
  // Time has passed without edges: reports the pending change if it has lasted long enough.
  PhotoEyeChange advance_to(std::int64_t t_ns) noexcept;

  bool present() const noexcept { return present_; }
  const PhotoEyeCounts& counts() const noexcept { return counts_; }

 private:
  PhotoEyeParameters parameters_;
  bool present_ = false;  // the reported state
  bool raw_ = false;      // the level after the latest edge
  bool seen_edge_ = false;
  std::int64_t last_edge_t_ns_ = 0;
  std::int64_t burst_start_t_ns_ = 0;
  std::int64_t burst_tag_ = 0;
  PhotoEyeCounts counts_;
};

}  // namespace cosmos
