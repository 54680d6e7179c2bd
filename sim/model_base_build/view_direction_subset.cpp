#include "sim/model_base_build/view_direction_subset.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/view_sphere.hpp"

namespace cosmos {
namespace {

// 0 for face centres, 1 for the other once-subdivided face middles, 2 for the rest.
int tier_of(int index) {
  const int child = (index % 16) / 4, grandchild = index % 4;
  if (grandchild != 3) return 2;
  return child == 3 ? 0 : 1;
}

}  // namespace

std::vector<int> spread_view_subset(int count) {
  if (count < 1 || count > kFullViewCount)
    throw std::invalid_argument("view count " + std::to_string(count) + " outside [1, 320]");
  const std::vector<Eigen::Vector3d> directions = view_directions(kViewSphereSubdivisions);
  const int n = static_cast<int>(directions.size());
  std::vector<int> order;
  std::vector<bool> taken(static_cast<std::size_t>(n), false);
  // Smallest angle-proxy (chord length) from each direction to the taken ones.
  std::vector<double> distance(static_cast<std::size_t>(n),
                               std::numeric_limits<double>::infinity());
  for (int tier = 0; tier <= 2 && static_cast<int>(order.size()) < count; ++tier) {
    while (static_cast<int>(order.size()) < count) {
      int best = -1;
      for (int i = 0; i < n; ++i) {
        if (taken[static_cast<std::size_t>(i)] || tier_of(i) != tier) continue;
        if (best < 0 ||
            distance[static_cast<std::size_t>(i)] > distance[static_cast<std::size_t>(best)])
          best = i;
      }
      if (best < 0) break;
      taken[static_cast<std::size_t>(best)] = true;
      order.push_back(best);
      for (int i = 0; i < n; ++i)
        distance[static_cast<std::size_t>(i)] = std::min(
            distance[static_cast<std::size_t>(i)],
            (directions[static_cast<std::size_t>(i)] - directions[static_cast<std::size_t>(best)])
                .norm());
    }
  }
  std::sort(order.begin(), order.end());
  return order;
}

}  // namespace cosmos
