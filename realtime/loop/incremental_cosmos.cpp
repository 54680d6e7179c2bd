#include "realtime/loop/incremental_cosmos.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cosmos {

namespace {

constexpr int kRingRows = 3;

}  // namespace

int IncrementalCosmos::fit_window_rows(const CosmosParameters& parameters) {
  // A stage runs at most two rows behind the one it reads from (smooth_next's ring gate), so
  // the rows still read span at most: the fit's reach twice (the rows it reads below and
  // above), the links' row on either side, two per smoothing level and the last row's store.
  const int fit_reach = 2 * std::max(parameters.fit.window_size / 2, 1);
  const int span = 2 * fit_reach + 2 * std::max(parameters.smoothing.iterations, 0) + 4;
  return span + std::max(span / 2, 16);
}

IncrementalCosmos::IncrementalCosmos(const CosmosParameters& parameters, int width, int max_rows,
                                     double pixel_size_x_mm, double pixel_size_y_mm,
                                     RowBlockPool& pool)
    : parameters_(parameters),
      width_(width),
      max_rows_(max_rows),
      fitter_(parameters.fit, pixel_size_x_mm, pixel_size_y_mm, width),
      window_(width, fit_window_rows(parameters), pixel_size_x_mm, pixel_size_y_mm),
      fitted_(width, fit_window_rows(parameters)),
      final_(width, kRingRows),
      classified_(make_shape_index_field(width, kRingRows)),
      rows_store_(pool, max_rows),
      seeds_(parameters.segmentation, width, max_rows),
      belt_words_per_row_((std::max(width, 0) + 63) / 64),
      belt_bits_(static_cast<std::size_t>(std::max(max_rows, 0)) * belt_words_per_row_, 0),
      smoothed_rows_(std::max(parameters.smoothing.iterations, 0), 0),
      smoothed_columns_(static_cast<std::size_t>(std::max(max_rows, 0)), {0, 0}) {
  for (int level = 1; level < parameters.smoothing.iterations; ++level)
    rings_.emplace_back(static_cast<std::size_t>(kRingRows) * kFrameComponents * width, 0.0f);
}

void IncrementalCosmos::begin_part(double origin_x_mm, double origin_y_mm) {
  rows_store_.clear();
  seeds_.begin_part();
  origin_x_mm_ = origin_x_mm;
  origin_y_mm_ = origin_y_mm;
  // The fit writes x and y from the window's origin; only its heights, frames, validity and
  // links are read (positions come from x_mm and y_mm), so the origin need not follow the
  // window's first row.
  window_.origin_x_mm = origin_x_mm;
  window_.origin_y_mm = origin_y_mm;
  window_first_row_ = 0;
  rows_ = fitted_rows_ = linked_rows_ = classified_rows_ = 0;
  std::fill(smoothed_rows_.begin(), smoothed_rows_.end(), 0);
  finished_ = false;
  fitter_.reset();
}

AddRowResult IncrementalCosmos::add_row(const float* z_mm, const std::uint8_t* belt) {
  if (rows_ >= max_rows_ || finished_) return AddRowResult::kTooLong;
  int begin = 0;
  while (begin < width_ && std::isnan(z_mm[begin])) ++begin;
  int end = width_;
  while (end > begin && std::isnan(z_mm[end - 1])) --end;
  if (!rows_store_.append(begin, end)) return AddRowResult::kNoMemory;
  make_room_in_window();
  std::copy(z_mm, z_mm + width_, window_.z_mm.row(in_window(rows_)));
  const PartRow record = rows_store_.row(rows_);
  std::copy(z_mm + begin, z_mm + end, record.z_mm);
  // No part's until the tracker says (the scan loop labels the row after adding it).
  std::fill(record.tracker_label, record.tracker_label + (end - begin), std::int64_t{-1});
  std::uint64_t* belt_row =
      belt_bits_.data() + static_cast<std::size_t>(rows_) * belt_words_per_row_;
  std::fill(belt_row, belt_row + belt_words_per_row_, 0);
  if (belt)
    for (int column = 0; column < width_; ++column)
      belt_row[column / 64] |= static_cast<std::uint64_t>(belt[column] != 0) << (column % 64);
  ++rows_;
  while (advance_one_row_each()) {
  }
  return AddRowResult::kAdded;
}

// Keeps room in the window for the new row and, below it, the rows finish() blanks (the
// fit's reach and the links' border row). When the window is full, the rows some stage still
// reads move to its top.
void IncrementalCosmos::make_room_in_window() {
  const int height = window_.height();
  if (in_window(rows_) + fit_reach_rows() + 2 <= height) return;
  int keep = std::min({fitted_rows_ - fit_reach_rows(), linked_rows_ - 1, classified_rows_});
  for (int done : smoothed_rows_) keep = std::min(keep, done - 1);
  keep = std::max(keep, window_first_row_);
  const int shift = keep - window_first_row_;
  const int kept = rows_ - keep;
  const auto move_up = [&](auto& grid) {
    std::copy(grid.row(shift), grid.row(shift + kept), grid.row(0));
  };
  move_up(window_.z_mm);
  move_up(fitted_.valid);
  move_up(fitted_.same_side);
  move_up(fitted_.position_mm[2]);
  for (auto& component : fitted_.frame) move_up(component);
  window_first_row_ = keep;
  // The separable fit's cached row filters are keyed by window row, which has changed.
  fitter_.reset();
}

void IncrementalCosmos::finish() {
  if (finished_) return;
  finished_ = true;
  // Below the part there is no data, whatever an earlier part left there (a crease window,
  // shifted by up to half a window, looks a whole window further), and the row below has no
  // valid fit (its links) — as at the border of a whole image.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int row = rows_; row < rows_ + fit_reach_rows(); ++row)
    std::fill(window_.z_mm.row(in_window(row)), window_.z_mm.row(in_window(row)) + width_, nan);
  std::fill(fitted_.valid.row(in_window(rows_)), fitted_.valid.row(in_window(rows_)) + width_, 0);
  while (advance_one_row_each()) {
  }
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
  fitter_.fit_row(window_, in_window(row), fitted_);
  ++fitted_rows_;
  return true;
}

bool IncrementalCosmos::link_next() {
  const int row = linked_rows_;
  if (row >= fitted_rows_ || !(row + 1 < fitted_rows_ || (finished_ && fitted_rows_ == rows_)))
    return false;
  fitter_.link_row(window_, in_window(row), fitted_);
  ++linked_rows_;
  return true;
}

const float* IncrementalCosmos::frame_row(int level, int component, int row) const {
  const int last = static_cast<int>(smoothed_rows_.size());
  if (level == 0) return fitted_.frame[component].row(in_window(row));
  if (level == last) return final_.frame[component].row(row % kRingRows);
  return rings_[level - 1].data() +
         (static_cast<std::size_t>(row % kRingRows) * kFrameComponents + component) * width_;
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
  // A ring row may be overwritten only once the level above (or the classification) has
  // used it.
  if (level < last && row >= kRingRows && smoothed_rows_[level] < row - 1) return false;
  if (level == last && row >= classified_rows_ + kRingRows) return false;
  const int window_row = in_window(row);
  SmoothingRowInput in;
  in.width = width_;
  in.valid = fitted_.valid.row(window_row);
  in.same_side = fitted_.same_side.row(window_row);
  // A part covers a fraction of the belt's width: smooth only between the row's first and
  // last valid pixel (found once, at level 1); the invalid pixels outside keep their frames.
  if (level == 1)
    smoothed_columns_[static_cast<std::size_t>(row)] = valid_column_extent(in.valid, width_);
  in.column_begin = smoothed_columns_[static_cast<std::size_t>(row)][0];
  in.column_end = smoothed_columns_[static_cast<std::size_t>(row)][1];
  const int rows[3] = {std::max(row - 1, 0), row, std::min(row + 1, rows_ - 1)};
  in.pixel_size_x_mm = static_cast<float>(window_.pixel_size_x_mm);
  in.pixel_size_y_mm = static_cast<float>(window_.pixel_size_y_mm);
  for (int r = 0; r < 3; ++r) {
    in.z_mm[r] = fitted_.position_mm[2].row(in_window(rows[r]));
    for (int c = 0; c < kFrameComponents; ++c) in.frame[r][c] = frame_row(level - 1, c, rows[r]);
  }
  float* out[kFrameComponents];
  for (int c = 0; c < kFrameComponents; ++c) out[c] = writable_frame_row(level, c, row);
  smooth_frame_row(in, out, parameters_.smoothing);
  if (level == last) {
    const int slot = row % kRingRows;
    std::copy(in.valid, in.valid + width_, final_.valid.row(slot));
    std::copy(in.same_side, in.same_side + width_, final_.same_side.row(slot));
  }
  ++smoothed_rows_[level - 1];
  return true;
}

bool IncrementalCosmos::classify_next() {
  const int row = classified_rows_;
  const bool smoothing = !smoothed_rows_.empty();
  const int done = smoothing ? smoothed_rows_.back() : linked_rows_;
  if (row >= done) return false;
  const int slot = row % kRingRows;
  if (!smoothing) {
    // No smoothing: the fitted frames are the final ones.
    const int window_row = in_window(row);
    std::copy(fitted_.valid.row(window_row), fitted_.valid.row(window_row) + width_,
              final_.valid.row(slot));
    std::copy(fitted_.same_side.row(window_row), fitted_.same_side.row(window_row) + width_,
              final_.same_side.row(slot));
    for (int c = 0; c < kFrameComponents; ++c)
      std::copy(fitted_.frame[c].row(window_row), fitted_.frame[c].row(window_row) + width_,
                final_.frame[c].row(slot));
  }
  classify_row(final_, slot, window_.pixel_size_x_mm, window_.pixel_size_y_mm,
               parameters_.shape_index, classified_);
  store_final_row(row, slot);
  SeedRowInput planes;
  planes.width = width_;
  planes.label = classified_.label.row(slot);
  planes.label_above = classified_.label.row((row + kRingRows - 1) % kRingRows);
  planes.shape_index = classified_.shape_index.row(slot);
  planes.same_side = classified_.same_side.row(slot);
  for (int axis = kNx; axis <= kNz; ++axis) planes.normal[axis] = final_.frame[axis].row(slot);
  seeds_.add_row(planes, rows_store_.row(row), rows_store_);
  ++classified_rows_;
  return true;
}

// The row's final planes into its compact record; the window's rows of it may go after this.
void IncrementalCosmos::store_final_row(int row, int slot) {
  const PartRow out = rows_store_.row(row);
  const int b = out.column_begin, e = out.column_end;
  const auto copy = [b, e](const auto* from, auto* to) { std::copy(from + b, from + e, to); };
  copy(fitted_.position_mm[2].row(in_window(row)), out.fitted_z_mm);
  copy(final_.valid.row(slot), out.valid);
  copy(final_.same_side.row(slot), out.same_side);
  for (int c = 0; c < kFrameComponents; ++c) copy(final_.frame[c].row(slot), out.frame[c]);
  copy(classified_.label.row(slot), out.label);
  copy(classified_.shape_index.row(slot), out.shape_index);
  copy(classified_.curvedness_per_mm.row(slot), out.curvedness_per_mm);
  copy(classified_.area_mm2.row(slot), out.area_mm2);
}

RangeImage IncrementalCosmos::whole_image() const {
  RangeImage image(width_, rows_, window_.pixel_size_x_mm, window_.pixel_size_y_mm);
  image.origin_x_mm = origin_x_mm_;
  image.origin_y_mm = origin_y_mm_;
  image.belt_seen = PixelGrid<std::uint8_t>(width_, rows_, 0);
  for (int r = 0; r < rows_; ++r) {
    const PartRow in = row(r);
    std::copy(in.z_mm, in.z_mm + (in.column_end - in.column_begin),
              image.z_mm.row(r) + in.column_begin);
    for (int column = 0; column < width_; ++column)
      image.belt_seen(column, r) = belt_seen(column, r) ? 1 : 0;
  }
  return image;
}

DarbouxFrameField IncrementalCosmos::whole_frames() const {
  DarbouxFrameField frames(width_, rows_);
  for (int r = 0; r < rows_; ++r) {
    const PartRow in = row(r);
    const int n = in.column_end - in.column_begin, b = in.column_begin;
    for (int c = 0; c < width_; ++c) {
      frames.position_mm[0](c, r) = x_mm(c);
      frames.position_mm[1](c, r) = y_mm(r);
    }
    std::copy(in.fitted_z_mm, in.fitted_z_mm + n, frames.position_mm[2].row(r) + b);
    std::copy(in.valid, in.valid + n, frames.valid.row(r) + b);
    std::copy(in.same_side, in.same_side + n, frames.same_side.row(r) + b);
    for (int k = 0; k < kFrameComponents; ++k)
      std::copy(in.frame[k], in.frame[k] + n, frames.frame[k].row(r) + b);
  }
  return frames;
}

ShapeIndexField IncrementalCosmos::whole_field() const {
  ShapeIndexField field = make_shape_index_field(width_, rows_);
  for (int r = 0; r < rows_; ++r) {
    const PartRow in = row(r);
    for (int c = in.column_begin; c < in.column_end; ++c) {
      const std::size_t k = in.at(c);
      field.label(c, r) = in.label[k];
      field.shape_index(c, r) = in.shape_index[k];
      field.curvedness_per_mm(c, r) = in.curvedness_per_mm[k];
      field.area_mm2(c, r) = in.area_mm2[k];
      // As classify_row: the links of the pixels it labels.
      field.same_side(c, r) = in.label[k] != SurfaceLabel::kInvalid ? in.same_side[k] : 0;
    }
  }
  return field;
}

}  // namespace cosmos
