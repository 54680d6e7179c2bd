#include "core/region_merge_queue.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

void RegionMergeQueue::reserve(std::size_t regions, std::size_t edges) {
  parent_.reserve(regions);
  min_.reserve(regions);
  max_.reserve(regions);
  area_mm2_.reserve(regions);
  buckets_[0].reserve(edges);
}

int RegionMergeQueue::add_region(float shape_index_min, float shape_index_max, float area_mm2) {
  parent_.push_back(static_cast<std::int32_t>(parent_.size()));
  min_.push_back(shape_index_min);
  max_.push_back(shape_index_max);
  area_mm2_.push_back(area_mm2);
  return static_cast<int>(parent_.size()) - 1;
}

int RegionMergeQueue::bucket_of(float diameter) {
  const int bucket = static_cast<int>(std::ceil(diameter * kBuckets));
  return std::clamp(bucket, 0, kBuckets);
}

float RegionMergeQueue::merged_diameter(int a, int b) const {
  return std::max(max_[a], max_[b]) - std::min(min_[a], min_[b]);
}

void RegionMergeQueue::add_edge(int a, int b) {
  // Pairs that would land in the first bucket are merged at once: the first bucket is popped
  // before anything else anyway, and merging while filing keeps most pixel pairs of a smooth
  // surface out of the queue.
  const int root_a = find(a), root_b = find(b);
  if (root_a == root_b) return;
  const int bucket = bucket_of(merged_diameter(root_a, root_b));
  if (bucket == 0) {
    unite(root_a, root_b);
  } else {
    buckets_[bucket].push_back({a, b});
  }
}

int RegionMergeQueue::find(int region) {
  while (parent_[region] != region) {
    parent_[region] = parent_[parent_[region]];  // path halving
    region = parent_[region];
  }
  return region;
}

void RegionMergeQueue::count_regions_of_area_at_least(float area_mm2) {
  significant_area_mm2_ = area_mm2;
  significant_regions_ = 0;
  for (std::size_t r = 0; r < parent_.size(); ++r)
    if (parent_[r] == static_cast<std::int32_t>(r) && area_mm2_[r] >= area_mm2) ++significant_regions_;
}

void RegionMergeQueue::unite(int a, int b) {
  a = find(a);
  b = find(b);
  if (a == b) return;
  significant_regions_ -= (area_mm2_[a] >= significant_area_mm2_) + (area_mm2_[b] >= significant_area_mm2_);
  significant_regions_ += area_mm2_[a] + area_mm2_[b] >= significant_area_mm2_;
  // Union by area keeps trees shallow; ties by index keep it deterministic.
  if (area_mm2_[a] < area_mm2_[b] || (area_mm2_[a] == area_mm2_[b] && a > b)) std::swap(a, b);
  parent_[b] = a;
  min_[a] = std::min(min_[a], min_[b]);
  max_[a] = std::max(max_[a], max_[b]);
  area_mm2_[a] += area_mm2_[b];
}

void RegionMergeQueue::grow(double shape_diameter_limit) {
  for (const Edge& edge : deferred_) buckets_[bucket_of(merged_diameter(find(edge.a), find(edge.b)))].push_back(edge);
  deferred_.clear();
  const float limit = static_cast<float>(shape_diameter_limit);
  const int last_bucket = bucket_of(limit);
  for (int bucket = 0; bucket <= last_bucket; ++bucket) {
    auto& edges = buckets_[bucket];
    while (!edges.empty()) {
      const Edge edge = edges.back();
      edges.pop_back();
      const int a = find(edge.a), b = find(edge.b);
      if (a == b) continue;
      const float diameter = merged_diameter(a, b);
      const int current = bucket_of(diameter);
      if (current > bucket) {
        buckets_[current].push_back(edge);  // the regions grew since the edge was filed
      } else if (diameter > limit) {
        deferred_.push_back(edge);
      } else {
        unite(a, b);
      }
    }
  }
}

}  // namespace cosmos
