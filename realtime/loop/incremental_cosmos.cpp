#include "realtime/loop/incremental_cosmos.hpp"

#include <algorithm>
#include <limits>

namespace cosmos {

IncrementalCosmos::IncrementalCosmos(const CosmosParameters& parameters, int width, int max_rows,
                                     double pixel_size_x_mm, double pixel_size_y_mm)
    : parameters_(parameters),
      width_(width),
      max_rows_(max_rows),
      fitter_(parameters.fit, pixel_size_x_mm, pixel_size_y_mm, width),
      image_(width, max_rows, pixel_size_x_mm, pixel_size_y_mm),
      fitted_(width, max_rows),
      frames_(width, max_rows),
      field_(make_shape_index_field(width, max_rows)),
      smoothed_rows_(std::max(parameters.smoothing.iterations, 0), 0),
      smoothed_columns_(static_cast<std::size_t>(max_rows), {0, 0}) {
  for (int level = 1; level < parameters.smoothing.iterations; ++level)
    rings_.emplace_back(static_cast<std::size_t>(3) * kFrameComponents * width, 0.0f);
}

void IncrementalCosmos::begin_part(double origin_x_mm, double origin_y_mm) {
  image_.origin_x_mm = origin_x_mm;
  image_.origin_y_mm = origin_y_mm;
  rows_ = fitted_rows_ = linked_rows_ = classified_rows_ = 0;
  std::fill(smoothed_rows_.begin(), smoothed_rows_.end(), 0);
  finished_ = false;
  fitter_.reset();
}

bool IncrementalCosmos::add_row(const float* z_mm) {
  if (rows_ >= max_rows_ || finished_) return false;
  std::copy(z_mm, z_mm + width_, image_.z_mm.row(rows_));
  ++rows_;
  while (advance_one_row_each()) {
  }
  return true;
}

void IncrementalCosmos::finish() {
  if (finished_) return;
  finished_ = true;
  // Below the part there is no data, whatever an earlier part left there (a crease window,
  // shifted by up to half a window, looks a whole window further), and the row below has no
  // valid fit (its links) — as at the border of a whole image.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int row = rows_; row < std::min(rows_ + fit_reach_rows(), max_rows_); ++row)
    std::fill(image_.z_mm.row(row), image_.z_mm.row(row) + width_, nan);
  if (rows_ < max_rows_) std::fill(fitted_.valid.row(rows_), fitted_.valid.row(rows_) + width_, 0);
  while (advance_one_row_each()) {
  }
  for (int row = rows_; row < max_rows_; ++row)
    std::fill(field_.label.row(row), field_.label.row(row) + width_, SurfaceLabel::kInvalid);
}

// Consumers first, one row per stage, so that no stage runs more than a row or two ahead of
// the next and the three-row rings never overwrite a row still needed.
bool IncrementalCosmos::advance_one_row_each() {
  bool progressed = classify_next();
  for (int level = static_cast<int>(smoothed_rows_.size()); level >= 1; --level)
    progressed = smooth_next(level) || progressed;
  progressed = link_next() || progressed;
  progressed = fit_next() || progressed;
  return progressed;
}

bool IncrementalCosmos::fit_next() {
  const int row = fitted_rows_;
  if (row >= rows_ || !(row + fit_reach_rows() < rows_ || finished_)) return false;
  fitter_.fit_row(image_, row, fitted_);
  ++fitted_rows_;
  return true;
}

bool IncrementalCosmos::link_next() {
  const int row = linked_rows_;
  if (row >= fitted_rows_ || !(row + 1 < fitted_rows_ || (finished_ && fitted_rows_ == rows_)))
    return false;
  fitter_.link_row(image_, row, fitted_);
  ++linked_rows_;
  return true;
}

const float* IncrementalCosmos::frame_row(int level, int component, int row) const {
  const int last = static_cast<int>(smoothed_rows_.size());
  if (level == 0) return fitted_.frame[component].row(row);
  if (level == last) return frames_.frame[component].row(row);
  return rings_[level - 1].data() +
         (static_cast<std::size_t>(row % 3) * kFrameComponents + component) * width_;
}

float* IncrementalCosmos::writable_frame_row(int level, int component, int row) {
  return const_cast<float*>(frame_row(level, component, row));
}

bool IncrementalCosmos::smooth_next(int level) {
  const int last = static_cast<int>(smoothed_rows_.size());
  const int row = smoothed_rows_[level - 1];
  // Rows available at the level below: links gate level 1 (its same-side masks).
  const int below =
      level == 1 ? std::min(fitted_rows_, linked_rows_ + 1) : smoothed_rows_[level - 2];
  const bool below_complete =
      level == 1 ? (finished_ && linked_rows_ == rows_) : (finished_ && below == rows_);
  if (row >= rows_ || (level == 1 && row >= linked_rows_)) return false;
  if (!(row + 1 < below || below_complete)) return false;
  // A ring row may be overwritten only once the level above has used it.
  if (level < last && row >= 3 && smoothed_rows_[level] < row - 1) return false;
  SmoothingRowInput in;
  in.width = width_;
  in.valid = fitted_.valid.row(row);
  in.same_side = fitted_.same_side.row(row);
  // A part covers a fraction of the belt's width: smooth only between the row's first and
  // last valid pixel (found once, at level 1); the invalid pixels outside keep their frames.
  if (level == 1)
    smoothed_columns_[static_cast<std::size_t>(row)] = valid_column_extent(in.valid, width_);
  in.column_begin = smoothed_columns_[static_cast<std::size_t>(row)][0];
  in.column_end = smoothed_columns_[static_cast<std::size_t>(row)][1];
  const int rows[3] = {std::max(row - 1, 0), row, std::min(row + 1, rows_ - 1)};
  in.pixel_size_x_mm = static_cast<float>(image_.pixel_size_x_mm);
  in.pixel_size_y_mm = static_cast<float>(image_.pixel_size_y_mm);
  for (int r = 0; r < 3; ++r) {
    in.z_mm[r] = fitted_.position_mm[2].row(rows[r]);
    for (int c = 0; c < kFrameComponents; ++c) in.frame[r][c] = frame_row(level - 1, c, rows[r]);
  }
  float* out[kFrameComponents];
  for (int c = 0; c < kFrameComponents; ++c) out[c] = writable_frame_row(level, c, row);
  smooth_frame_row(in, out, parameters_.smoothing);
  if (level == last) {
    std::copy(fitted_.valid.row(row), fitted_.valid.row(row) + width_, frames_.valid.row(row));
    std::copy(fitted_.same_side.row(row), fitted_.same_side.row(row) + width_,
              frames_.same_side.row(row));
    for (int axis = 0; axis < 3; ++axis)
      std::copy(fitted_.position_mm[axis].row(row), fitted_.position_mm[axis].row(row) + width_,
                frames_.position_mm[axis].row(row));
  }
  ++smoothed_rows_[level - 1];
  return true;
}

bool IncrementalCosmos::classify_next() {
  const int row = classified_rows_;
  const bool smoothing = !smoothed_rows_.empty();
  const int done = smoothing ? smoothed_rows_.back() : linked_rows_;
  if (row >= done) return false;
  classify_row(smoothing ? frames_ : fitted_, row, image_.pixel_size_x_mm, image_.pixel_size_y_mm,
               parameters_.shape_index, field_);
  ++classified_rows_;
  return true;
}

}  // namespace cosmos
