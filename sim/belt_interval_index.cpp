#include "sim/belt_interval_index.hpp"

namespace cosmos {

void BeltIntervalIndex::rebuild(const std::vector<Eigen::AlignedBox3d>& boxes) {
  entries_.clear();
  longest_mm_ = 0.0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (boxes[i].isEmpty()) continue;
    entries_.push_back({boxes[i].min().y(), boxes[i].max().y(), static_cast<int>(i)});
    longest_mm_ = std::max(longest_mm_, boxes[i].max().y() - boxes[i].min().y());
  }
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    return a.y_low_mm != b.y_low_mm ? a.y_low_mm < b.y_low_mm : a.item < b.item;
  });
}

}  // namespace cosmos
