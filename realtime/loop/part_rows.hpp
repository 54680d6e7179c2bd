#pragma once
// A part's finished rows, kept compactly in blocks of a RowBlockPool: each row holds only the
// columns between its first and last sample ([column_begin, column_end)), since a pixel
// without a sample has no fit, no frame and no label (local_surface_fit.hpp: a fit needs the
// pixel's own sample; curvature_consistency.hpp: invalid pixels keep the neutral frame) and
// the tracker labels only sampled pixels. The pixels outside are those defaults, which
// PartRow::holds() lets a reader skip. A row's record is taken when its profile arrives (its
// heights and tracker labels) and completed when its COSMOS is final (frames and labels).
//
// Records are laid end to end in the part's current block; a record that does not fit takes
// the next block. Nothing here allocates after construction.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/segmentation/seed_union_find.hpp"
#include "core/surface/darboux_frame_field.hpp"
#include "core/surface/shape_index.hpp"
#include "realtime/loop/row_block_pool.hpp"

namespace cosmos {

// One row's planes, indexed by column - column_begin. Positions are not stored: x and y are
// the grid's (IncrementalCosmos::x_mm, y_mm), z the fitted height.
struct PartRow {
  int column_begin = 0;
  int column_end = 0;
  std::int64_t* tracker_label = nullptr;  // tracker part id, -1 none
  SeedNode* seed_node = nullptr;          // the CSMP seed search's pass-1 nodes (row_seeds.hpp)
  float* z_mm = nullptr;                  // the conditioned height, NaN none
  float* fitted_z_mm = nullptr;           // the local fit's height, 0 where it failed
  float* frame[kFrameComponents] = {};    // smoothed normal and Weingarten tensor
  float* shape_index = nullptr;
  float* curvedness_per_mm = nullptr;
  float* area_mm2 = nullptr;
  std::uint8_t* valid = nullptr;
  std::uint8_t* same_side = nullptr;
  SurfaceLabel* label = nullptr;

  bool holds(int column) const { return column >= column_begin && column < column_end; }
  std::size_t at(int column) const { return static_cast<std::size_t>(column - column_begin); }
};

class PartRows {
 public:
  PartRows(RowBlockPool& pool, int max_rows);
  PartRows(const PartRows&) = delete;
  PartRows& operator=(const PartRows&) = delete;
  ~PartRows();

  // Bytes of the record of a row of `columns` columns (a multiple of 8).
  static std::size_t record_bytes(int columns);

  // Room for row rows() with columns [column_begin, column_end); false, nothing changed,
  // when max_rows rows are held or the pool has no block left.
  bool append(int column_begin, int column_end);
  // `bytes` more of the part's data (rounded up to 8) after the records so far, in the same
  // blocks: a row's seed crossings (row_seeds.hpp). Null when no block has room.
  std::byte* take_bytes(std::size_t bytes);
  // Gives every block back to the pool; rows() is 0 after.
  void clear();

  int rows() const { return rows_; }
  int blocks() const { return static_cast<int>(blocks_.size()); }
  // The recognizer reads the rows the acquisition thread wrote before handing the part over.
  PartRow row(int r) const { return rows_table_[static_cast<std::size_t>(r)]; }

 private:
  RowBlockPool& pool_;
  int max_rows_;
  std::vector<PartRow> rows_table_;  // max_rows entries
  std::vector<int> blocks_;          // capacity: every block of the pool
  std::size_t used_in_block_ = 0;    // bytes of the last block taken
  int rows_ = 0;
};

}  // namespace cosmos
