#pragma once
// Constrained region growing over a region-adjacency graph (§3.5.2): union-find regions that
// remember their shape-index range, and a bucket queue of adjacency edges keyed by the shape
// diameter (max S_I - min S_I) the merged region would have. Costs only grow as regions grow,
// so stale edges are re-filed lazily when popped. Growing can be resumed with a larger limit
// (the adaptive mode of §5.4.3) without starting over. Deterministic: integer buckets, LIFO
// within a bucket.
#include <cstdint>
#include <vector>

namespace cosmos {

class RegionMergeQueue {
 public:
  // Regions are created with add_region() in index order, edges with add_edge().
  void reserve(std::size_t regions);
  int add_region(float shape_index_min, float shape_index_max, float area_mm2);
  void add_edge(int a, int b);

  // Merges adjacent pairs, least merged shape diameter first, while it is <= limit.
  void grow(double shape_diameter_limit);

  // From now on, keep count of the regions of at least this area (the adaptive mode's
  // criterion), updated by every merge.
  void count_regions_of_area_at_least(float area_mm2);
  int significant_region_count() const { return significant_regions_; }

  int find(int region) {
    while (regions_[region].parent != region) {
      Region& r = regions_[region];
      r.parent = regions_[r.parent].parent;  // path halving
      region = r.parent;
    }
    return region;
  }
  bool is_root(int region) const { return regions_[region].parent == region; }
  void unite(int a, int b);  // unconditional merge (used to fold tiny patches)
  float area_mm2(int root) const { return regions_[root].area_mm2; }
  float shape_index_min(int root) const { return regions_[root].min; }
  float shape_index_max(int root) const { return regions_[root].max; }
  std::size_t region_count() const { return regions_.size(); }

 private:
  // One cache line holds a region's parent and, at a root, everything a merge test reads.
  struct Region {
    std::int32_t parent;
    float min;
    float max;
    float area_mm2;
  };
  // The last known roots of the two sides; find() of them gives the current roots.
  struct Edge {
    std::int32_t a;
    std::int32_t b;
  };
  static constexpr int kBuckets = 256;  // over shape diameters [0, 1]: 0.0039 wide
  float merged_diameter(int root_a, int root_b) const;
  static int bucket_of(float diameter);
  void merge_roots(int a, int b);

  std::vector<Region> regions_;
  std::vector<std::vector<Edge>> buckets_ = std::vector<std::vector<Edge>>(kBuckets + 1);
  std::vector<Edge> deferred_;  // popped edges above the current limit, kept for a resume
  float significant_area_mm2_ = 0;
  int significant_regions_ = 0;
};

}  // namespace cosmos
