#include "realtime/loop/row_seeds.hpp"

#include <algorithm>

#include "core/segmentation/neighbor_equality.hpp"

namespace cosmos {

RowSeeds::RowSeeds(const SegmentationParameters& parameters, int width, int max_rows)
    : enabled_(width <= (1 << kColumnBits) && max_rows < (1 << (31 - kColumnBits))),
      width_(std::max(width, 0)),
      quantum_(static_cast<float>(parameters.seed_shape_index_quantum)),
      crease_cos_(seed_crease_cos(parameters)),
      rows_(static_cast<std::size_t>(std::max(max_rows, 0))),
      ids_above_(static_cast<std::size_t>(width_), -1),
      ids_(static_cast<std::size_t>(width_), -1),
      edges_(static_cast<std::size_t>(width_), 0),
      same_id_(static_cast<std::size_t>(width_), 0),
      row_crossings_(static_cast<std::size_t>(kBackwardNeighbors) * width_) {
  for (auto& plane : normal_above_) plane.assign(static_cast<std::size_t>(width_), 0.0f);
}

void RowSeeds::begin_part() {
  seeded_rows_ = 0;
  pair_count_ = 0;
  pairs_overflowed_ = crossings_lost_ = false;
  last_crossing_ = {-1, -1};
}

void RowSeeds::add_row(const SeedRowInput& planes, const PartRow& record, PartRows& store) {
  const int row = seeded_rows_;
  if (!enabled_ || row >= static_cast<int>(rows_.size())) return;
  SeedRowInput input = planes;
  if (row == 0) input.label_above = nullptr;
  for (int axis = 0; axis < 3; ++axis)
    input.normal_above[axis] = row > 0 ? normal_above_[axis].data() : nullptr;
  // A row's pixels outside its samples have no label (part_rows.hpp): the pass need not
  // visit them, and they have no node.
  input.column_begin = record.column_begin;
  input.column_end = record.column_end;
  backward_seed_edges(input, crease_cos_, edges_.data());
  list_linked_ids(row, record, edges_.data());

  RowNodes& nodes_of_row = rows_[static_cast<std::size_t>(row)];
  nodes_of_row = {record.seed_node, record.column_begin, record.column_end, nullptr, 0};
  Nodes nodes{rows_.data(), row};
  int crossings = 0;
  auto add_crossing = [&](std::int32_t root, std::int32_t other) {
    const std::pair<std::int32_t, std::int32_t> crossing{root, other};
    if (crossing == last_crossing_) return;
    last_crossing_ = crossing;
    row_crossings_[static_cast<std::size_t>(crossings)] = crossing;
    ++crossings;
  };
  grow_seeds_in_row(input, edges_.data(), quantum_, nodes, add_crossing);
  // The row's crossings into the part's blocks, as many as there are.
  if (crossings > 0) {
    const std::size_t bytes = static_cast<std::size_t>(crossings) * sizeof(row_crossings_[0]);
    std::byte* room = store.take_bytes(bytes);
    if (!room) {
      crossings_lost_ = true;
    } else {
      nodes_of_row.crossings = reinterpret_cast<std::pair<std::int32_t, std::int32_t>*>(room);
      std::copy(row_crossings_.begin(), row_crossings_.begin() + crossings, nodes_of_row.crossings);
      nodes_of_row.crossing_count = crossings;
    }
  }

  for (int axis = 0; axis < 3; ++axis)
    std::copy(planes.normal[axis] + record.column_begin, planes.normal[axis] + record.column_end,
              normal_above_[axis].begin() + record.column_begin);
  ++seeded_rows_;
}

// The pairs of tracker ids a growing edge of this row joins.
void RowSeeds::list_linked_ids(int row, const PartRow& record, const std::uint8_t* edges) {
  // Full rows of ids, -1 outside the samples: the row two back leaves only its own span to
  // clear.
  std::swap(ids_above_, ids_);
  std::swap(ids_above_span_, ids_span_);
  std::fill(ids_.begin() + ids_span_[0], ids_.begin() + ids_span_[1], -1);
  ids_span_ = {record.column_begin, record.column_end};
  std::copy(record.tracker_label, record.tracker_label + (record.column_end - record.column_begin),
            ids_.begin() + record.column_begin);
  equal_backward_neighbors(row > 0 ? ids_above_.data() : nullptr, ids_.data(), width_,
                           record.column_begin, record.column_end, same_id_.data());
  for (int column = record.column_begin; column < record.column_end; ++column) {
    const auto crossing = static_cast<std::uint8_t>(edges[column] & ~same_id_[column]);
    if (crossing == 0) continue;
    for (int k = 0; k < kBackwardNeighbors; ++k) {
      if (!((crossing >> k) & 1u)) continue;
      const std::int64_t other =
          (kNeighborOffsets[k].row < 0
               ? ids_above_
               : ids_)[static_cast<std::size_t>(column + kNeighborOffsets[k].column)];
      const std::pair<std::int64_t, std::int64_t> pair{std::min(ids_[column], other),
                                                       std::max(ids_[column], other)};
      if (std::find(linked_ids_.begin(), linked_ids_.begin() + pair_count_, pair) !=
          linked_ids_.begin() + pair_count_)
        continue;
      if (pair_count_ == kMaxLinkedIdPairs) {
        pairs_overflowed_ = true;
        continue;
      }
      linked_ids_[static_cast<std::size_t>(pair_count_++)] = pair;
    }
  }
}

std::optional<ShapeSeeds> RowSeeds::view_seeds(const ShapeIndexField& view,
                                               int first_column) const {
  const int width = view.width(), height = view.height();
  if (!enabled_ || seeded_rows_ < height) return std::nullopt;
  // The view's index of a builder pixel id, -1 outside the view.
  const auto view_index = [&](std::int32_t id) -> std::int32_t {
    const int row = id >> kColumnBits, x = (id & kColumnMask) - first_column;
    if (row >= height || x < 0 || x >= width) return -1;
    return row * width + x;
  };
  // A set reaching outside the view's pixels (which holds_part rules out) leaves the seeds
  // unusable.
  bool outside = false;
  ShapeSeeds seeds = number_shape_seeds(view, [&](int row, int x) -> SeedNode {
    const RowNodes& from = rows_[static_cast<std::size_t>(row)];
    const int column = x + first_column;
    const std::int32_t own = row * width + x;
    if (column < from.column_begin || column >= from.column_end) {
      outside = true;
      return {own, 0, 0};
    }
    const SeedNode& node = from.nodes[column - from.column_begin];
    const std::int32_t parent = node.parent == kNotSeeded ? -1 : view_index(node.parent);
    if (parent < 0 || parent > own ||
        view.label[static_cast<std::size_t>(parent)] == SurfaceLabel::kInvalid) {
      outside = true;
      return {own, 0, 0};
    }
    return {parent, node.low, node.high};
  });
  if (outside) return std::nullopt;
  // The crossings of the view's pixels, in the order pass 1 found them; one repeating the one
  // before it is dropped, as a pass over the view alone drops it.
  std::vector<std::pair<std::int32_t, std::int32_t>> crossings;
  for (int row = 0; row < height; ++row) {
    const RowNodes& from = rows_[static_cast<std::size_t>(row)];
    for (int n = 0; n < from.crossing_count; ++n) {
      const std::int32_t root = view_index(from.crossings[n].first);
      if (root < 0 || view.label[static_cast<std::size_t>(root)] == SurfaceLabel::kInvalid)
        continue;
      const std::int32_t other = view_index(from.crossings[n].second);
      if (other < 0) return std::nullopt;
      const std::pair<std::int32_t, std::int32_t> crossing{root, other};
      if (crossings.empty() || crossings.back() != crossing) crossings.push_back(crossing);
    }
  }
  list_seed_pairs(crossings, seeds);
  return seeds;
}

}  // namespace cosmos
