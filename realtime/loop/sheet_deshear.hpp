#pragma once
// De-shearing of the conditioned rows of a pitched laser sheet. The COSMOS grid takes every
// row for a slice of the belt at one position: true of an upright sheet, and of the model
// views, which are rendered with one. A sheet tilted about x by p from the belt normal shears
// every profile along the belt instead: its sample at in-sheet height s stands s·cos p above
// the belt and s·sin p along the belt from the sheet's foot. So a sample of input row i with
// conditioned height s belongs at the fractional row r = i − s·sin p / grid_mm (p > 0: a high
// sample to an earlier row), height h = s·cos p. Resampling within a profile cannot undo
// that: the rows must be resampled across each other, which is what this class does.
//
// Forward scatter, column by column: consecutive samples of a column whose heights differ by
// at most the COSMOS fit's depth jump are one surface, and the segment between them in
// (r, h) is interpolated linearly onto every whole row it spans. A sample that starts or
// ends such a chain also lands on its nearest row (within half a row) unless the chain
// already covers that row; a lone sample (across a jump or beside no data) lands there only.
// Where surfaces overlap on a cell the highest wins: the top surface, as the conditioner
// keeps it within a profile. Surfaces higher than max_height_mm are dropped and counted.
// The sheet never lights the side of a wall facing away from it, nor the belt just behind
// it, and spreads its samples apart on a surface falling away from it: where consecutive
// samples there differ by more than the depth jump they are not joined, and a row between
// them stays empty: two samples cannot tell such a surface from a step whose shadow lies
// between them, and a step is not to be bridged.
//
// Output row k is final once input row k + D has arrived, D = ceil(max_height_mm·|tan p| /
// grid_mm + 1/2): a sample shifts by at most max_height_mm·|tan p| / grid_mm rows, and the
// half row is its nearest-row landing, decided only when the next row shows whether its chain
// goes on. Belt flags pass through from input row k unchanged (the belt, at height ~0, is
// not shifted). All memory is taken at construction: a ring of 2D + 2 rows. With p = 0 the
// class is the identity with D = 0.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "scanner/conditioning_parameters.hpp"

namespace cosmos {

class SheetDeshear {
 public:
  // A window longer than this is a typo (4,096 rows of 0.4 mm are 1.6 m of belt); the cell
  // config refuses it.
  static constexpr int kMaxWindowRows = 4096;
  // D for these parameters: 0 for an upright sheet; kMaxWindowRows + 1 for any longer window.
  static int window_rows(const ConditioningParameters& parameters);

  // `depth_jump_mm`: the COSMOS fit's, across which the conditioner never interpolates either.
  // Parameters whose window exceeds kMaxWindowRows give one of kMaxWindowRows + 1 rows, which
  // higher samples than it reaches fall outside of (clamped to its last row).
  SheetDeshear(const ConditioningParameters& parameters, double depth_jump_mm, int width);

  bool active() const { return delay_ > 0; }
  int delay() const { return delay_; }
  int width() const { return width_; }

  // The next input row: width() heights above the belt (NaN = no data) and belt flags
  // (nullptr: none seen). True when an output row is final, then row() and belt() hold it
  // until the next push. No allocation, no lock, no throw.
  bool push(const float* z_mm, const std::uint8_t* belt);
  // An input row of no data, to drain the D rows still pending at the end of a stream.
  bool push_empty() { return push(nullptr, nullptr); }
  const float* row() const { return out_z_; }
  const std::uint8_t* belt() const { return out_belt_; }
  // The empty rows to push for every pushed row to come out: the delay once a row was
  // pushed since the start or clear(), else 0.
  int pending() const;
  // Forgets every pending row: the next push starts a new stream.
  void clear();

  // Samples higher than max_height_mm, dropped as no data.
  std::int64_t samples_too_high() const { return samples_too_high_; }

 private:
  // A column's sample of the previous input row. Row positions are doubles: whole rows stay
  // exact for as long as a belt can run.
  struct Sample {
    double r = 0;  // fractional row position
    float h = 0;
    bool valid = false;
    bool chained = false;  // joined to the sample before it in its column
    double r_before = 0;   // that sample's row position, when chained
  };
  std::size_t slot(std::int64_t row) const;
  // The highest surface wins a cell. `row` is kept within the rows still open, which only
  // rounding at the window's very edge could leave.
  void land(std::int64_t row, int column, float h);
  void land_nearest(const Sample& sample, int column);
  void land_segment(const Sample& a, const Sample& b, int column);
  static bool spans(double a, double b, std::int64_t row);

  int width_;
  int delay_ = 0;
  double shift_rows_per_mm_ = 0;  // sin p / grid_mm
  float cos_pitch_ = 1;
  float depth_jump_mm_;
  float max_height_mm_;
  std::int64_t ring_rows_ = 1;
  std::vector<float> ring_z_;            // ring_rows_ x width_, NaN = nothing landed
  std::vector<std::uint8_t> ring_belt_;  // ring_rows_ x width_: the input rows' flags
  std::vector<Sample> last_;             // per column: the previous input row's sample
  std::int64_t next_input_ = 0;          // input rows pushed since the start or clear()
  std::int64_t open_first_ = 0;          // the rows a push may still land on
  std::int64_t open_last_ = 0;
  const float* out_z_ = nullptr;
  const std::uint8_t* out_belt_ = nullptr;
  std::int64_t samples_too_high_ = 0;
};

}  // namespace cosmos
