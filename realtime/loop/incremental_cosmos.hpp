#pragma once
// The chapter-3 pipeline of one part, advanced one row at a time as its profiles arrive: the
// local surface fit of row r once rows up to r + h exist, its same-side links, then the 15
// curvature-consistency iterations pipelined row by row (iteration k of row r needs
// iteration k-1 of rows r-1..r+1 only, kept in three-row rings), shape index, curvedness and
// planar label, and the first pass of the CSMP seed search (row_seeds.hpp). The same row
// kernels as whole-image processing (core/), applied in the same arithmetic order, so the
// fields equal analyze_view()'s of the part's rows bit for bit; the recognizer worker ends the
// pipeline with finish_view_analysis() on the part's own pixels (the spectrum is not
// accumulated here: a builder's rows also hold other parts' pixels).
//
// Memory follows the part, not the belt: the rows the pipeline still works on sit in a
// window of a few dozen full rows (fit_window_rows()), and a row whose COSMOS is final moves
// into the part's compact rows (part_rows.hpp), taken from a pool shared by the builders.
// Every working buffer is sized at construction: adding a row never allocates.
#include <array>
#include <cstdint>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/range_image.hpp"
#include "core/surface/curvature_consistency.hpp"
#include "core/surface/darboux_frame_field.hpp"
#include "core/surface/local_surface_fit.hpp"
#include "core/surface/shape_index.hpp"
#include "realtime/loop/part_rows.hpp"
#include "realtime/loop/row_block_pool.hpp"
#include "realtime/loop/row_seeds.hpp"

namespace cosmos {

enum class AddRowResult {
  kAdded,
  kTooLong,   // max_rows rows held (or the part finished): the row is dropped
  kNoMemory,  // the pool had no block for the row: nothing changed
};

class IncrementalCosmos {
 public:
  IncrementalCosmos(const CosmosParameters& parameters, int width, int max_rows,
                    double pixel_size_x_mm, double pixel_size_y_mm, RowBlockPool& pool);

  // Starts a part; the rows of the previous one must have been released (release_rows).
  void begin_part(double origin_x_mm, double origin_y_mm);
  // Appends one row of `width` heights (mm, NaN = no data) and, when given, its belt flags
  // (1 where the belt itself was measured: ProfileConditioner::condition's out_belt).
  AddRowResult add_row(const float* z_mm, const std::uint8_t* belt = nullptr);
  // Runs the pipeline to the last row (the bottom border of the part).
  void finish();
  // Gives the part's rows back to the pool (the recognizer is done with them).
  void release_rows() { rows_store_.clear(); }

  int rows() const { return rows_; }
  int max_rows() const { return max_rows_; }
  // Rows below a pixel that its fit may read: a whole window, since a crease window is
  // shifted by up to half of one (local_surface_fit.hpp). A row is fitted only once they
  // have arrived, so it never reads a row of an earlier part.
  int fit_reach_rows() const { return 2 * (parameters_.fit.window_size / 2); }
  // Rows whose COSMOS is final, [0, final_rows()): stored, and never written again.
  int final_rows() const { return classified_rows_; }
  int width() const { return width_; }
  // Row r of the part; its COSMOS planes are final once finish() has run.
  PartRow row(int r) const { return rows_store_.row(r); }
  int blocks() const { return rows_store_.blocks(); }
  // The CSMP seed search's first pass over the final rows (row_seeds.hpp).
  const RowSeeds& seeds() const { return seeds_; }
  double origin_x_mm() const { return origin_x_mm_; }
  double origin_y_mm() const { return origin_y_mm_; }
  // A pixel's fitted position in x and y: the grid's, as the local fit writes them.
  float x_mm(int column) const {
    return static_cast<float>(origin_x_mm_ + column * window_.pixel_size_x_mm);
  }
  float y_mm(int row) const {
    return static_cast<float>(origin_y_mm_ + row * window_.pixel_size_y_mm);
  }
  // Whether the belt was measured at a pixel of the part's rows (false without belt flags).
  bool belt_seen(int column, int row) const {
    const std::uint64_t word =
        belt_bits_[static_cast<std::size_t>(row) * belt_words_per_row_ + column / 64];
    return ((word >> (column % 64)) & 1u) != 0;
  }
  // The part's rows as whole images of width x rows() (tests and tools: these allocate).
  RangeImage whole_image() const;
  DarbouxFrameField whole_frames() const;
  ShapeIndexField whole_field() const;

  // Full rows of the working window: the rows from the oldest one a stage still reads to the
  // newest, twice over, so that moving them to the window's top is rare.
  static int fit_window_rows(const CosmosParameters& parameters);

 private:
  // The window row of part row `row`.
  int in_window(int row) const { return row - window_first_row_; }
  void make_room_in_window();
  bool advance_one_row_each();
  bool fit_next();
  bool link_next();
  bool smooth_next(int level);
  bool classify_next();
  void store_final_row(int row, int slot);
  // Frame rows of smoothing level `level` (0 = fitted, iterations = final), row clamped to
  // the part's rows as whole-image processing does.
  const float* frame_row(int level, int component, int row) const;
  float* writable_frame_row(int level, int component, int row);

  CosmosParameters parameters_;
  int width_;
  int max_rows_;
  LocalSurfaceFitter fitter_;
  // Part rows [window_first_row_, window_first_row_ + window height): the heights the fit
  // reads and level 0 (fitted frames, heights, validity and links) that smoothing reads.
  RangeImage window_;
  DarbouxFrameField fitted_;
  int window_first_row_ = 0;
  std::vector<std::vector<float>> rings_;  // levels 1 .. iterations-1: 3 rows x components
  DarbouxFrameField final_;                // the last level (frames, validity, links): 3 rows
  ShapeIndexField classified_;             // 3 rows
  PartRows rows_store_;
  RowSeeds seeds_;
  // Per row, a bit per column: the belt measured there (the surface-seen test tells a shadow
  // from the belt by it). Full rows, a bit each: max_rows x width / 8 bytes.
  int belt_words_per_row_ = 0;
  std::vector<std::uint64_t> belt_bits_;
  double origin_x_mm_ = 0;
  double origin_y_mm_ = 0;

  int rows_ = 0;
  bool finished_ = false;
  int fitted_rows_ = 0;
  int linked_rows_ = 0;
  std::vector<int> smoothed_rows_;  // per level 1 .. iterations
  // Per row: the columns smoothing writes, [begin, end) (smooth_next).
  std::vector<std::array<int, 2>> smoothed_columns_;
  int classified_rows_ = 0;
};

}  // namespace cosmos
