#include "realtime/loop/sheet_deshear.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cosmos {

namespace {

constexpr float kNoData = std::numeric_limits<float>::quiet_NaN();

}  // namespace

// The largest shift a sample up to max_height_mm gets, in rows, plus the half row of its
// nearest-row landing.
int SheetDeshear::window_rows(const ConditioningParameters& parameters) {
  if (parameters.sheet_pitch_deg == 0) return 0;
  const double tan_pitch = std::abs(std::tan(parameters.sheet_pitch_deg * std::numbers::pi / 180));
  const double rows = std::ceil(parameters.max_height_mm * tan_pitch / parameters.grid_mm + 0.5);
  // Written as "not within" so that NaN is refused too.
  return !(rows <= kMaxWindowRows) ? kMaxWindowRows + 1 : static_cast<int>(rows);
}

SheetDeshear::SheetDeshear(const ConditioningParameters& parameters, double depth_jump_mm,
                           int width)
    : width_(std::max(width, 1)),
      delay_(window_rows(parameters)),
      shift_rows_per_mm_(std::sin(parameters.sheet_pitch_deg * std::numbers::pi / 180) /
                         parameters.grid_mm),
      cos_pitch_(static_cast<float>(std::cos(parameters.sheet_pitch_deg * std::numbers::pi / 180))),
      depth_jump_mm_(static_cast<float>(depth_jump_mm)),
      max_height_mm_(static_cast<float>(parameters.max_height_mm)),
      ring_rows_(2 * static_cast<std::int64_t>(delay_) + 2),
      ring_z_(static_cast<std::size_t>(ring_rows_ * width_), kNoData),
      ring_belt_(static_cast<std::size_t>(ring_rows_ * width_), 0),
      last_(static_cast<std::size_t>(width_)) {}

std::size_t SheetDeshear::slot(std::int64_t row) const {
  // Rows before the stream's first (a high sample of one of its first rows) wrap too.
  return static_cast<std::size_t>(((row % ring_rows_) + ring_rows_) % ring_rows_) *
         static_cast<std::size_t>(width_);
}

int SheetDeshear::pending() const { return next_input_ > 0 ? delay_ : 0; }

void SheetDeshear::clear() {
  std::fill(ring_z_.begin(), ring_z_.end(), kNoData);
  std::fill(ring_belt_.begin(), ring_belt_.end(), std::uint8_t{0});
  std::fill(last_.begin(), last_.end(), Sample{});
  next_input_ = 0;
}

void SheetDeshear::land(std::int64_t row, int column, float h) {
  float& cell =
      ring_z_[slot(std::clamp(row, open_first_, open_last_)) + static_cast<std::size_t>(column)];
  if (!(cell >= h)) cell = h;  // NaN compares false: the first landing takes the cell
}

void SheetDeshear::land_nearest(const Sample& sample, int column) {
  land(static_cast<std::int64_t>(std::floor(sample.r + 0.5)), column, sample.h);
}

bool SheetDeshear::spans(double a, double b, std::int64_t row) {
  const auto r = static_cast<double>(row);
  return r >= std::min(a, b) && r <= std::max(a, b);
}

void SheetDeshear::land_segment(const Sample& a, const Sample& b, int column) {
  const double low = std::min(a.r, b.r), high = std::max(a.r, b.r);
  const double length = b.r - a.r;
  for (auto row = static_cast<std::int64_t>(std::ceil(low)); static_cast<double>(row) <= high;
       ++row) {
    // Both samples on one row (a vertical wall seen edge-on): its top.
    const float h =
        length == 0
            ? std::max(a.h, b.h)
            : a.h + static_cast<float>((static_cast<double>(row) - a.r) / length) * (b.h - a.h);
    land(row, column, h);
  }
}

bool SheetDeshear::push(const float* z_mm, const std::uint8_t* belt) {
  if (delay_ == 0) {
    // The identity: an upright sheet's rows are already slices at one belt position. Slot 0
    // stays an empty row for push_empty().
    out_z_ = z_mm ? z_mm : ring_z_.data();
    out_belt_ = belt ? belt : ring_belt_.data();
    ++next_input_;
    return true;
  }
  const std::int64_t input = next_input_;
  open_first_ = input - delay_;
  open_last_ = input + delay_;
  // The row this input opens last held row open_last_ - ring_rows_, emitted two pushes ago.
  std::fill_n(ring_z_.begin() + static_cast<std::ptrdiff_t>(slot(open_last_)), width_, kNoData);
  std::uint8_t* belt_row = ring_belt_.data() + slot(input);
  if (belt) {
    std::copy_n(belt, width_, belt_row);
  } else {
    std::fill_n(belt_row, width_, std::uint8_t{0});
  }
  for (int c = 0; c < width_; ++c) {
    Sample& previous = last_[static_cast<std::size_t>(c)];
    Sample sample;
    const float s = z_mm ? z_mm[c] : kNoData;
    if (!std::isnan(s)) {
      sample.h = s * cos_pitch_;
      sample.r = static_cast<double>(input) - static_cast<double>(s) * shift_rows_per_mm_;
      sample.valid = sample.h <= max_height_mm_;
      samples_too_high_ += sample.valid ? 0 : 1;
    }
    const bool joined =
        previous.valid && sample.valid && std::abs(sample.h - previous.h) <= depth_jump_mm_;
    if (previous.valid && !(previous.chained && joined)) {
      // The previous sample's own landing, now that this one shows whether its chain goes
      // on: alone, or at a chain's start or end beyond the rows its segment covers (within
      // a chain the segments cover every row between its ends).
      const auto nearest = static_cast<std::int64_t>(std::floor(previous.r + 0.5));
      const bool covered = (joined && spans(previous.r, sample.r, nearest)) ||
                           (previous.chained && spans(previous.r_before, previous.r, nearest));
      if (!covered) land_nearest(previous, c);
    }
    if (joined) land_segment(previous, sample, c);
    sample.chained = joined;
    sample.r_before = previous.r;
    previous = sample;
  }
  ++next_input_;
  if (input < delay_) return false;
  out_z_ = ring_z_.data() + slot(open_first_);
  out_belt_ = ring_belt_.data() + slot(open_first_);
  return true;
}

}  // namespace cosmos
