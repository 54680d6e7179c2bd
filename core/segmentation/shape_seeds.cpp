#include "core/segmentation/shape_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <numbers>
#include <span>

#include "core/segmentation/neighbor_equality.hpp"

namespace cosmos {
namespace {

// The nodes of a whole image: ids are raster indices.
struct RasterSeedNodes {
  SeedNode* nodes;
  std::int32_t width;
  std::int32_t row_start;  // the id of this row's column 0

  std::int32_t id(int column) const { return row_start + column; }
  std::int32_t above_id(int column) const { return row_start - width + column; }
  SeedNode& at(std::int32_t id) { return nodes[id]; }
  SeedNode& here(int column) { return nodes[row_start + column]; }
  SeedNode& above(int column) { return nodes[row_start - width + column]; }
};

// The table of recently listed seed pairs: 4096 entries, indexed by the top bits of a hash.
constexpr int kRecentShift = 20;
constexpr std::size_t kRecentPairs = std::size_t{1} << (32 - kRecentShift);

// The row of `field` (and the normals of `frames`) that pass 1 reads.
SeedRowInput seed_row_input(const DarbouxFrameField& frames, const ShapeIndexField& field,
                            int row) {
  SeedRowInput input;
  input.width = input.column_end = field.width();
  input.label = field.label.row(row);
  input.label_above = row > 0 ? field.label.row(row - 1) : nullptr;
  input.shape_index = field.shape_index.row(row);
  input.same_side = field.same_side.row(row);
  for (int axis = kNx; axis <= kNz; ++axis) {
    input.normal[axis] = frames.frame[axis].row(row);
    input.normal_above[axis] = row > 0 ? frames.frame[axis].row(row - 1) : nullptr;
  }
  return input;
}

}  // namespace

void backward_seed_edges(const SeedRowInput& row, double crease_cos, std::uint8_t* edges) {
  const int begin = row.column_begin, end = row.column_end;
  equal_backward_neighbors(row.label_above, row.label, row.width, begin, end, edges);
  for (int column = begin; column < end; ++column)
    edges[column] = static_cast<std::uint8_t>(edges[column] & row.same_side[column] & 0x0Fu);
  for (int column = begin; column < end; ++column) {
    if (row.label[column] != SurfaceLabel::kPlanar || edges[column] == 0) continue;
    for (int k = 0; k < kBackwardNeighbors; ++k) {
      if (!((edges[column] >> k) & 1u)) continue;
      const int other = column + kNeighborOffsets[k].column;
      const float* const* normal = kNeighborOffsets[k].row < 0 ? row.normal_above : row.normal;
      double cosine = 0;
      for (int axis = kNx; axis <= kNz; ++axis)
        cosine += row.normal[axis][column] * normal[axis][other];
      if (cosine < crease_cos) edges[column] &= static_cast<std::uint8_t>(~(1u << k));
    }
  }
}

double seed_crease_cos(const SegmentationParameters& parameters) {
  return std::cos(parameters.planar_crease_deg * std::numbers::pi / 180.0);
}

ShapeSeeds find_shape_seeds(const DarbouxFrameField& frames, const ShapeIndexField& field,
                            const SegmentationParameters& parameters) {
  const std::size_t pixels = field.label.size();
  const double crease_cos = seed_crease_cos(parameters);
  // Pass 1 (seed_union_find.hpp). A crossing repeating the one before it (the same two sets
  // along a boundary) is listed once.
  const std::unique_ptr<SeedNode[]> node_storage(new SeedNode[pixels]);
  RasterSeedNodes nodes{node_storage.get(), field.width(), 0};
  std::vector<std::uint8_t> row_edges(static_cast<std::size_t>(field.width()));
  std::vector<std::pair<std::int32_t, std::int32_t>> crossings;
  crossings.reserve(pixels / 4);
  auto add_crossing = [&](std::int32_t root, std::int32_t other) {
    const std::pair<std::int32_t, std::int32_t> crossing{root, other};
    if (crossings.empty() || crossings.back() != crossing) crossings.push_back(crossing);
  };
  const auto quantum = static_cast<float>(parameters.seed_shape_index_quantum);
  for (int row = 0; row < field.height(); ++row) {
    const SeedRowInput input = seed_row_input(frames, field, row);
    backward_seed_edges(input, crease_cos, row_edges.data());
    nodes.row_start = row * field.width();
    grow_seeds_in_row(input, row_edges.data(), quantum, nodes, add_crossing);
  }
  const SeedNode* node = node_storage.get();
  ShapeSeeds seeds = number_shape_seeds(
      field, [node, width = field.width()](int row, int column) -> const SeedNode& {
        return node[static_cast<std::size_t>(row) * width + column];
      });
  list_seed_pairs(crossings, seeds);
  return seeds;
}

void list_seed_pairs(std::span<const std::pair<std::int32_t, std::int32_t>> crossings,
                     ShapeSeeds& seeds) {
  const std::vector<std::int32_t>& seed_of_pixel = seeds.seed_of_pixel;
  // Pass 3: the crossings between different seeds. Along a boundary the same pair recurs from
  // pixel to pixel and row to row: a small table of recently listed pairs, indexed by a hash
  // of the pair, keeps nearly all repeats out of the list. The scan runs backwards so that a
  // pair keeps the place of its last crossing, as the unfiltered list's last copy would have
  // in the growing queue (keeping first copies changed the relief views' segmentations).
  seeds.adjacent.reserve(crossings.size() / 2);
  std::vector<std::uint64_t> recent(kRecentPairs, ~std::uint64_t{0});
  for (auto crossing = crossings.rbegin(); crossing != crossings.rend(); ++crossing) {
    const std::int32_t a = seed_of_pixel[crossing->first], b = seed_of_pixel[crossing->second];
    if (a == b) continue;
    const auto low = static_cast<std::uint32_t>(std::min(a, b));
    const auto high = static_cast<std::uint32_t>(std::max(a, b));
    const std::uint64_t key = std::uint64_t{low} << 32 | high;
    std::uint64_t& slot = recent[(low * 0x9E3779B1u ^ high * 0x85EBCA77u) >> kRecentShift];
    if (slot == key) continue;
    slot = key;
    seeds.adjacent.emplace_back(b, a);
  }
  std::reverse(seeds.adjacent.begin(), seeds.adjacent.end());
}

}  // namespace cosmos
