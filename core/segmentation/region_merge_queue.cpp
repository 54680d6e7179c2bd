#include "core/segmentation/region_merge_queue.hpp"

#include <algorithm>
#include <utility>

namespace cosmos {
namespace {
constexpr std::size_t kPrefetchDistance = 16;
}  // namespace

void RegionMergeQueue::reserve(std::size_t regions) { regions_.reserve(regions); }

int RegionMergeQueue::add_region(float shape_index_min, float shape_index_max, float area_mm2) {
  const auto index = static_cast<std::int32_t>(regions_.size());
  regions_.push_back({index, shape_index_min, shape_index_max, area_mm2});
  return index;
}

// ceil(diameter * kBuckets) clamped to [0, kBuckets]; the product is exact (a power of two)
// and diameters are never negative, so truncating and rounding up a fraction is the ceiling.
int RegionMergeQueue::bucket_of(float diameter) {
  const float scaled = diameter * kBuckets;
  if (!(scaled < kBuckets)) return kBuckets;
  const int whole = static_cast<int>(scaled);
  return std::max(0, whole + (static_cast<float>(whole) < scaled));
}

float RegionMergeQueue::merged_diameter(int a, int b) const {
  return std::max(regions_[a].max, regions_[b].max) - std::min(regions_[a].min, regions_[b].min);
}

void RegionMergeQueue::add_edge(int a, int b) {
  // Pairs that would land in the first bucket are merged at once: the first bucket is popped
  // before anything else anyway, and merging while filing keeps most pixel pairs of a smooth
  // surface out of the queue.
  const int root_a = find(a), root_b = find(b);
  if (root_a == root_b) return;
  const int bucket = bucket_of(merged_diameter(root_a, root_b));
  if (bucket == 0) {
    merge_roots(root_a, root_b);
  } else {
    buckets_[bucket].push_back({root_a, root_b});
  }
}

void RegionMergeQueue::count_regions_of_area_at_least(float area_mm2) {
  significant_area_mm2_ = area_mm2;
  significant_regions_ = 0;
  for (std::size_t r = 0; r < regions_.size(); ++r)
    if (regions_[r].parent == static_cast<std::int32_t>(r) && regions_[r].area_mm2 >= area_mm2)
      ++significant_regions_;
}

void RegionMergeQueue::unite(int a, int b) {
  a = find(a);
  b = find(b);
  if (a != b) merge_roots(a, b);
}

void RegionMergeQueue::merge_roots(int a, int b) {
  Region* ra = &regions_[a];
  Region* rb = &regions_[b];
  significant_regions_ -=
      (ra->area_mm2 >= significant_area_mm2_) + (rb->area_mm2 >= significant_area_mm2_);
  significant_regions_ += ra->area_mm2 + rb->area_mm2 >= significant_area_mm2_;
  // Union by area keeps trees shallow; ties by index keep it deterministic.
  if (ra->area_mm2 < rb->area_mm2 || (ra->area_mm2 == rb->area_mm2 && a > b)) {
    std::swap(a, b);
    std::swap(ra, rb);
  }
  rb->parent = a;
  ra->min = std::min(ra->min, rb->min);
  ra->max = std::max(ra->max, rb->max);
  ra->area_mm2 += rb->area_mm2;
}

void RegionMergeQueue::grow(double shape_diameter_limit) {
  for (const Edge& edge : deferred_) {
    const int a = find(edge.a), b = find(edge.b);
    buckets_[bucket_of(merged_diameter(a, b))].push_back({a, b});
  }
  deferred_.clear();
  const float limit = static_cast<float>(shape_diameter_limit);
  const int last_bucket = bucket_of(limit);
  for (int bucket = 0; bucket <= last_bucket; ++bucket) {
    auto& edges = buckets_[bucket];
    while (!edges.empty()) {
      if (edges.size() > kPrefetchDistance) {
        // The stack is popped in order: fetch the regions of an edge a few pops ahead.
        const Edge& ahead = edges[edges.size() - 1 - kPrefetchDistance];
        __builtin_prefetch(&regions_[ahead.a]);
        __builtin_prefetch(&regions_[ahead.b]);
      }
      const Edge edge = edges.back();
      edges.pop_back();
      const int a = find(edge.a), b = find(edge.b);
      if (a == b) continue;
      const float diameter = merged_diameter(a, b);
      const int current = bucket_of(diameter);
      if (current > bucket) {
        buckets_[current].push_back({a, b});  // the regions grew since the edge was filed
      } else if (diameter > limit) {
        deferred_.push_back({a, b});
      } else {
        merge_roots(a, b);
      }
    }
  }
}

}  // namespace cosmos
