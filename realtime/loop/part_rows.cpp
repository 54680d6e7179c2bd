#include "realtime/loop/part_rows.hpp"

#include <algorithm>

namespace cosmos {

namespace {

// The planes of a record, widest first so that each stays aligned to its type (a seed node is
// three 4-byte words).
constexpr int kFloatPlanes = 2 + kFrameComponents + 3;  // z, fitted z, frame, S_I, C, area
constexpr int kBytePlanes = 3;                          // valid, same_side, label

}  // namespace

PartRows::PartRows(RowBlockPool& pool, int max_rows)
    : pool_(pool), max_rows_(std::max(max_rows, 0)) {
  rows_table_.resize(static_cast<std::size_t>(max_rows_));
  blocks_.reserve(static_cast<std::size_t>(pool.block_count()));
}

PartRows::~PartRows() { clear(); }

std::size_t PartRows::record_bytes(int columns) {
  const auto n = static_cast<std::size_t>(std::max(columns, 0));
  const std::size_t bytes =
      n * (sizeof(std::int64_t) + sizeof(SeedNode) + kFloatPlanes * sizeof(float) + kBytePlanes);
  return (bytes + 7) / 8 * 8;
}

std::byte* PartRows::take_bytes(std::size_t bytes) {
  bytes = (bytes + 7) / 8 * 8;
  if (bytes == 0 || bytes > pool_.block_bytes()) return nullptr;
  if (blocks_.empty() || used_in_block_ + bytes > pool_.block_bytes()) {
    const int block = pool_.acquire();
    if (block < 0) return nullptr;
    blocks_.push_back(block);
    used_in_block_ = 0;
  }
  std::byte* taken = pool_.data(blocks_.back()) + used_in_block_;
  used_in_block_ += bytes;
  return taken;
}

bool PartRows::append(int column_begin, int column_end) {
  if (rows_ >= max_rows_) return false;
  const int columns = std::max(column_end - column_begin, 0);
  std::byte* record = nullptr;
  if (columns > 0 && !(record = take_bytes(record_bytes(columns)))) return false;
  PartRow& row = rows_table_[static_cast<std::size_t>(rows_)];
  row.column_begin = column_begin;
  row.column_end = column_begin + columns;
  const auto n = static_cast<std::size_t>(columns);
  row.tracker_label = reinterpret_cast<std::int64_t*>(record);
  row.seed_node = reinterpret_cast<SeedNode*>(record + n * sizeof(std::int64_t));
  auto* floats = reinterpret_cast<float*>(row.seed_node + n);
  row.z_mm = floats;
  row.fitted_z_mm = floats + n;
  for (int c = 0; c < kFrameComponents; ++c) row.frame[c] = floats + (2 + c) * n;
  row.shape_index = floats + (2 + kFrameComponents) * n;
  row.curvedness_per_mm = floats + (3 + kFrameComponents) * n;
  row.area_mm2 = floats + (4 + kFrameComponents) * n;
  auto* bytes_planes = reinterpret_cast<std::uint8_t*>(floats + kFloatPlanes * n);
  row.valid = bytes_planes;
  row.same_side = bytes_planes + n;
  row.label = reinterpret_cast<SurfaceLabel*>(bytes_planes + 2 * n);
  ++rows_;
  return true;
}

void PartRows::clear() {
  for (int block : blocks_) pool_.release(block);
  blocks_.clear();
  used_in_block_ = 0;
  rows_ = 0;
}

}  // namespace cosmos
