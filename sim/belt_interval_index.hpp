#pragma once
// The placed parts of a conveyor scene by their extent along the belt (y, belt frame): which
// of them a y interval meets. A belt of a thousand parts has only a few near the laser sheet,
// so the scanner and the ray tracer visit those, never every part of the run: their cost per
// profile does not grow with the length of the belt.
//
// Determinism: the parts are visited in one fixed order (by the start of their extent, ties by
// index), whatever order they were added or moved in.
#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

namespace cosmos {

class BeltIntervalIndex {
 public:
  // Indexes boxes[i] as item i (empty boxes are never visited). Allocates; not for a hot path.
  void rebuild(const std::vector<Eigen::AlignedBox3d>& boxes);

  // Calls visit(i) for every item whose y extent meets [y_low_mm, y_high_mm]. Allocation-free.
  template <class Visit>
  void for_each_meeting(double y_low_mm, double y_high_mm, Visit&& visit) const {
    // An extent no longer than longest_mm_ that meets the interval starts after this.
    const double earliest_start_mm = y_low_mm - longest_mm_;
    auto it = std::lower_bound(entries_.begin(), entries_.end(), earliest_start_mm,
                               [](const Entry& e, double y) { return e.y_low_mm < y; });
    for (; it != entries_.end() && it->y_low_mm <= y_high_mm; ++it) {
      if (it->y_high_mm >= y_low_mm) visit(it->item);
    }
  }

  int size() const { return static_cast<int>(entries_.size()); }

 private:
  struct Entry {
    double y_low_mm = 0.0;
    double y_high_mm = 0.0;
    int item = 0;
  };
  std::vector<Entry> entries_;  // by y_low_mm, then item
  double longest_mm_ = 0.0;
};

}  // namespace cosmos
