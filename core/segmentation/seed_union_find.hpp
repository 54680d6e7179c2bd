#pragma once
// Pass 1 of the seed search (shape_seeds.hpp), one row at a time: a union-find over pixels in
// raster order in which each pixel joins the sets of its already visited neighbours, the one
// giving the least joined S_I range first (the growing order of §3.5.2), while the joined
// range stays within seed_shape_index_quantum. A row needs only the row above it, so the pass
// runs over a whole image (find_shape_seeds) or row by row as the real-time part builder
// finishes each row's shape index (realtime/loop/row_seeds.hpp), with the same arithmetic in
// the same order: the two give the same sets.
//
// Where the storage of the nodes differs, a `Nodes` type says it, with pixel ids increasing in
// raster order (a set's root is its first pixel, the least id):
//   std::int32_t id(int column), above_id(int column)  this row's and the row above's ids
//   SeedNode& at(std::int32_t id), here(int column), above(int column)
// `add_crossing(root, other)` receives the sets a pixel touched but did not join: they may
// still join later through other pixels, so a crossing names pixels, resolved to seeds once
// seeds are numbered (number_shape_seeds).
#include <algorithm>
#include <cstdint>

#include "core/surface/darboux_frame_field.hpp"
#include "core/surface/shape_index.hpp"

namespace cosmos {

inline constexpr std::int32_t kNotSeeded = -1;  // a pixel without a label: in no set

// A pixel's union-find node; at a root, the S_I range of its set.
struct SeedNode {
  std::int32_t parent;
  float low;
  float high;
};

// The planes of one row that pass 1 reads, columns [0, width); pass 1 visits the columns
// [column_begin, column_end), outside which no pixel has a label.
struct SeedRowInput {
  int width = 0;
  int column_begin = 0;
  int column_end = 0;
  const SurfaceLabel* label = nullptr;
  const SurfaceLabel* label_above = nullptr;  // null on the first row
  const float* shape_index = nullptr;
  const std::uint8_t* same_side = nullptr;  // ShapeIndexField::same_side
  const float* normal[3] = {};              // n_x, n_y, n_z (planar creases)
  const float* normal_above[3] = {};
};

// Directions 0-3 of kNeighborOffsets (up-left, up, up-right, left) are the half of the
// 8-neighbourhood already visited in raster order: every adjacency is seen once, from its
// later pixel.
inline constexpr int kBackwardNeighbors = 4;

// The growing-edge masks of the columns [column_begin, column_end) of one row: bit k set when
// backward neighbour k is inside the image, on the same side of any depth jump and has the
// same label; planar pixels also need normals within the crease angle (cosine `crease_cos`).
void backward_seed_edges(const SeedRowInput& row, double crease_cos, std::uint8_t* edges);

template <class Nodes>
std::int32_t find_seed_root(Nodes& nodes, std::int32_t x) {
  while (nodes.at(x).parent != x) {
    SeedNode& node = nodes.at(x);
    node.parent = nodes.at(node.parent).parent;  // path halving
    x = node.parent;
  }
  return x;
}

// Pass 1 over one row, whose growing edges are `edges` (backward_seed_edges). Every node of
// the row is written before it is read: the nodes need no fill beforehand.
template <class Nodes, class AddCrossing>
void grow_seeds_in_row(const SeedRowInput& row, const std::uint8_t* edges, float quantum,
                       Nodes& nodes, AddCrossing&& add_crossing) {
  constexpr int kLeft = 3;
  std::int32_t left_root = kNotSeeded;
  for (int column = row.column_begin; column < row.column_end; ++column) {
    if (row.label[column] == SurfaceLabel::kInvalid) {
      nodes.here(column).parent = kNotSeeded;
      continue;
    }
    const std::uint8_t joined = edges[column];
    std::int32_t root = nodes.id(column);
    const float shape_index = row.shape_index[column];
    nodes.here(column) = {root, shape_index, shape_index};
    // Inside a seed, the pixels above point straight at the left pixel's root (the previous
    // pixel's, a root still): then it is the only seed to join, without a search, and the
    // pixel joins it when the joined range stays within one quantum (the loop below would
    // do the same, more slowly; half the pixels of a smooth view are inside).
    bool inside = (joined >> kLeft) & 1u;
    for (int k = 0; k < kLeft; ++k)
      inside &= !((joined >> k) & 1u) ||
                nodes.above(column + kNeighborOffsets[k].column).parent == left_root;
    if (inside) {
      SeedNode& left = nodes.at(left_root);
      if (std::max(shape_index, left.high) - std::min(shape_index, left.low) <= quantum) {
        left.low = std::min(left.low, shape_index);
        left.high = std::max(left.high, shape_index);
        nodes.here(column).parent = left_root;
      } else {
        add_crossing(root, left_root);
        left_root = root;
      }
      continue;
    }
    // Join the neighbours' seeds, the one whose joined S_I range is least first, while the
    // joined seed's range stays within one quantum.
    std::int32_t roots[kBackwardNeighbors], root_in_direction[kBackwardNeighbors];
    int count = 0;
    for (int k = 0; k < kBackwardNeighbors; ++k) {
      if (!((joined >> k) & 1u)) continue;
      const std::int32_t other =
          k == kLeft ? left_root
                     : find_seed_root(nodes, nodes.above_id(column + kNeighborOffsets[k].column));
      root_in_direction[k] = other;
      bool listed = false;
      for (int n = 0; n < count; ++n) listed |= roots[n] == other;
      if (!listed) roots[count++] = other;
    }
    while (count > 0) {
      int best = -1;
      float best_range = quantum;
      for (int n = 0; n < count; ++n) {
        const SeedNode& other = nodes.at(roots[n]);
        const SeedNode& own = nodes.at(root);
        const float range = std::max(own.high, other.high) - std::min(own.low, other.low);
        if (range <= best_range) best_range = range, best = n;
      }
      if (best < 0) break;
      const std::int32_t other = roots[best];
      roots[best] = roots[--count];
      // The joined set keeps the older root; the roots left in the list are untouched.
      const std::int32_t kept = std::min(root, other), joined_root = std::max(root, other);
      SeedNode& keeper = nodes.at(kept);
      const SeedNode& gone = nodes.at(joined_root);
      keeper.low = std::min(keeper.low, gone.low);
      keeper.high = std::max(keeper.high, gone.high);
      nodes.at(joined_root).parent = kept;
      root = kept;
    }
    if (count == 1) {
      add_crossing(root, roots[0]);
    } else if (count > 1) {
      // Edge by edge, in direction order, into the sets left unjoined (roots still, and not
      // this pixel's): the seed pairs then keep the order a scan of every growing edge gives
      // them, which orders ties in the growing queue.
      for (int k = 0; k < kBackwardNeighbors; ++k) {
        const std::int32_t other = root_in_direction[k];
        if (((joined >> k) & 1u) && other != root && nodes.at(other).parent == other)
          add_crossing(root, other);
      }
    }
    left_root = root;
  }
}

}  // namespace cosmos
