// De-shearing a pitched laser sheet's rows: a hemisphere and a box with vertical walls, scanned
// as a sheet pitched by ±1° and ±5° measures them (tests/realtime/loop/pitched_sheet.hpp),
// come out as the upright sheet's rows of the same surfaces: heights within the linear
// interpolation's error on the smooth parts, edges at most one row off. An upright sheet is
// the identity; the delay is the window; belt flags pass through; a push allocates nothing.
#include "realtime/loop/sheet_deshear.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "tests/common/allocation_counter.hpp"
#include "tests/realtime/loop/pitched_sheet.hpp"

namespace cosmos {
namespace {

constexpr double kGrid = 0.4;
constexpr int kWidth = 300;  // x in [-60, 60) mm
constexpr int kRows = 230;   // the scene's rows, y = row · grid
constexpr double kThreshold = 0.5;
constexpr double kDepthJump = 3.0;
constexpr double kTop = 30.0;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

double column_x(int column) { return -60.0 + column * kGrid; }

// A hemisphere of radius 30 mm at x = -28, y = 40 mm and a 20 mm box with vertical walls over
// x in [12, 48], y in [20.12, 60.24] mm (its walls between rows), on an empty belt.
double surface(double x, double y) {
  double z = 0;
  const double r2 = 900.0 - (x + 28) * (x + 28) - (y - 40) * (y - 40);
  if (r2 > 0) z = std::sqrt(r2);
  if (x >= 12 && x <= 48 && y >= 20.12 && y <= 60.24) z = std::max(z, 20.0);
  return z;
}

struct Rows {
  std::vector<float> z;  // kRows x kWidth, NaN: background
  std::vector<std::uint8_t> belt;
  float at(int row, int column) const {
    return row < 0 || row >= kRows ? kNaN : z[static_cast<std::size_t>(row * kWidth + column)];
  }
};

// Conditioned as ProfileConditioner does: heights under the threshold are background, and
// there the belt was seen.
void condition(double height, float& z, std::uint8_t& belt) {
  z = height >= kThreshold ? static_cast<float>(height) : kNaN;
  belt = height < kThreshold ? 1 : 0;
}

Rows upright_rows() {
  Rows rows{std::vector<float>(kRows * kWidth), std::vector<std::uint8_t>(kRows * kWidth)};
  for (int k = 0; k < kRows; ++k)
    for (int c = 0; c < kWidth; ++c) {
      const auto cell = static_cast<std::size_t>(k * kWidth + c);
      condition(surface(column_x(c), k * kGrid), rows.z[cell], rows.belt[cell]);
    }
  return rows;
}

Rows pitched_rows(double pitch_deg) {
  Rows rows{std::vector<float>(kRows * kWidth), std::vector<std::uint8_t>(kRows * kWidth)};
  for (int i = 0; i < kRows; ++i)
    for (int c = 0; c < kWidth; ++c) {
      const auto column = [c](double y) { return surface(column_x(c), y); };
      const auto cell = static_cast<std::size_t>(i * kWidth + c);
      condition(testing::pitched_sheet_hit(column, i * kGrid, pitch_deg, kTop), rows.z[cell],
                rows.belt[cell]);
    }
  return rows;
}

ConditioningParameters pitched(double pitch_deg, double max_height_mm = 40) {
  ConditioningParameters parameters;
  parameters.grid_mm = kGrid;
  parameters.height_threshold_mm = kThreshold;
  parameters.sheet_pitch_deg = pitch_deg;
  parameters.max_height_mm = max_height_mm;
  return parameters;
}

int expected_delay(double pitch_deg, double max_height_mm) {
  return static_cast<int>(
      std::ceil(max_height_mm * std::abs(std::tan(testing::radians(pitch_deg))) / kGrid + 0.5));
}

// The input rows through the de-shear, drained with empty rows: output row k of every input
// row k, and the belt flags it came out with.
Rows run_deshear(SheetDeshear& deshear, const Rows& input) {
  Rows out{std::vector<float>(kRows * kWidth), std::vector<std::uint8_t>(kRows * kWidth)};
  int emitted = 0;
  const auto take = [&] {
    std::copy_n(deshear.row(), kWidth, out.z.begin() + emitted * kWidth);
    std::copy_n(deshear.belt(), kWidth, out.belt.begin() + emitted * kWidth);
    ++emitted;
  };
  for (int i = 0; i < kRows; ++i)
    if (deshear.push(&input.z[static_cast<std::size_t>(i * kWidth)],
                     &input.belt[static_cast<std::size_t>(i * kWidth)]))
      take();
  EXPECT_EQ(deshear.pending(), deshear.delay());
  for (int k = deshear.pending(); k > 0; --k)
    if (deshear.push_empty()) take();
  EXPECT_EQ(emitted, kRows);
  return out;
}

struct Comparison {
  double smooth_error = 0;   // the largest height error on the smooth parts
  double smooth_excess = 0;  // beyond the interpolation's own error there
  int smooth_cells = 0;
  int edge_cells = 0;        // data on one side only, within a row of such an edge
  int steep_holes = 0;       // no data where the truth falls more than 1 mm per row
  int holes_per_column = 0;  // the most of them in one column
  int misplaced_cells = 0;   // data on one side only, neither of those
  double overshoot = 0;      // the most any output stands above the truth a row around it
  double box_top_error = 0;
};

bool has(float z) { return !std::isnan(z); }

Comparison compare(const Rows& out, const Rows& truth) {
  Comparison result;
  for (int c = 0; c < kWidth; ++c) {
    int holes = 0;
    for (int k = 0; k < kRows; ++k) {
      const float got = out.at(k, c), want = truth.at(k, c);
      if (has(got) != has(want)) {
        // An edge one row off: a neighbouring row of the truth agrees.
        const bool near =
            has(truth.at(k - 1, c)) == has(got) || has(truth.at(k + 1, c)) == has(got);
        // A surface falling away from the laser steeper than the depth jump per sample (the
        // pitched sheet's samples spread apart on it) is not interpolated: a row's hole.
        const bool steep = !has(got) && (std::abs(truth.at(k + 1, c) - want) > 1.0f ||
                                         std::abs(truth.at(k - 1, c) - want) > 1.0f);
        if (near) {
          ++result.edge_cells;
        } else if (steep) {
          ++result.steep_holes;
          ++holes;
        } else {
          ++result.misplaced_cells;
        }
      }
      if (has(got)) {
        float around = -1;
        for (int j = k - 1; j <= k + 1; ++j)
          if (has(truth.at(j, c))) around = std::max(around, truth.at(j, c));
        result.overshoot = std::max(result.overshoot, static_cast<double>(got - around));
      }
      const double x = column_x(c), y = k * kGrid;
      if (has(got) && x > 13 && x < 47 && y > 21.5 && y < 59) {
        result.box_top_error = std::max(result.box_top_error, std::abs(got - 20.0));
      }
      // Smooth: five rows of data around, no step over 0.4 mm (a slope of at most 45°).
      bool smooth = true;
      for (int j = k - 2; j <= k + 2 && smooth; ++j) smooth = has(truth.at(j, c));
      for (int j = k - 2; j < k + 2 && smooth; ++j)
        smooth = std::abs(truth.at(j + 1, c) - truth.at(j, c)) <= 0.4f;
      if (!smooth) continue;
      ++result.smooth_cells;
      const double error = has(got) ? std::abs(got - want) : 1e9;
      // Linear interpolation between samples at most 1.5 rows apart errs by up to
      // |h''|·1.5²/8 rows², h'' taken from the truth's second difference.
      const double second = std::abs(truth.at(k + 1, c) - 2 * want + truth.at(k - 1, c));
      result.smooth_error = std::max(result.smooth_error, error);
      result.smooth_excess = std::max(result.smooth_excess, error - 0.29 * second);
    }
    result.holes_per_column = std::max(result.holes_per_column, holes);
  }
  return result;
}

class PitchedSheet : public ::testing::TestWithParam<double> {};

TEST_P(PitchedSheet, DeshearedRowsAreTheUprightSheetsRows) {
  const double pitch = GetParam();
  SheetDeshear deshear(pitched(pitch), kDepthJump, kWidth);
  ASSERT_EQ(deshear.delay(), expected_delay(pitch, 40));
  const Rows input = pitched_rows(pitch);
  const Rows truth = upright_rows();
  const Rows out = run_deshear(deshear, input);
  const Comparison c = compare(out, truth);
  // The sheared input itself is far off: the test would notice no de-shear at all.
  const Comparison sheared = compare(input, truth);
  std::printf(
      "pitch %+.0f°: smooth cells %d, max error %.5f mm (%.5f beyond interpolation), box top "
      "%.6f mm, one-row edge cells %d, steep holes %d (%d a column at most), misplaced %d, "
      "overshoot %.4f mm; not de-sheared: max error %.3f mm, misplaced %d\n",
      pitch, c.smooth_cells, c.smooth_error, c.smooth_excess, c.box_top_error, c.edge_cells,
      c.steep_holes, c.holes_per_column, c.misplaced_cells, c.overshoot, sheared.smooth_error,
      sheared.misplaced_cells + sheared.steep_holes);
  EXPECT_GT(c.smooth_cells, 4000);
  // Float heights (1e-5 mm at 30 mm) and the hit's bisection are far below 0.005 mm; the
  // rest is the linear interpolation between samples along the belt.
  EXPECT_LE(c.smooth_excess, 0.005);
  EXPECT_LE(c.smooth_error, 0.02);
  EXPECT_LE(c.box_top_error, 1e-4);
  EXPECT_EQ(c.misplaced_cells, 0);
  EXPECT_LE(c.holes_per_column, 1);
  EXPECT_LE(c.overshoot, 0.02);
  EXPECT_GT(sheared.smooth_error, 0.2);
  // Belt flags pass through from input row k to output row k.
  EXPECT_EQ(out.belt, input.belt);
}

INSTANTIATE_TEST_SUITE_P(SheetDeshear, PitchedSheet, ::testing::Values(-5.0, -1.0, 1.0, 5.0),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return (info.param < 0 ? "minus" : "plus") +
                                  std::to_string(static_cast<int>(std::abs(info.param))) + "deg";
                         });

TEST(SheetDeshear, AnUprightSheetIsTheIdentity) {
  SheetDeshear deshear(pitched(0), kDepthJump, kWidth);
  EXPECT_FALSE(deshear.active());
  EXPECT_EQ(deshear.delay(), 0);
  const Rows input = pitched_rows(0);
  for (int i = 0; i < kRows; ++i) {
    const float* z = &input.z[static_cast<std::size_t>(i * kWidth)];
    const std::uint8_t* belt = &input.belt[static_cast<std::size_t>(i * kWidth)];
    ASSERT_TRUE(deshear.push(z, belt));
    EXPECT_EQ(std::memcmp(deshear.row(), z, kWidth * sizeof(float)), 0) << i;
    EXPECT_EQ(std::memcmp(deshear.belt(), belt, kWidth), 0) << i;
  }
  EXPECT_EQ(deshear.pending(), 0);
  ASSERT_TRUE(deshear.push_empty());
  EXPECT_TRUE(std::all_of(deshear.row(), deshear.row() + kWidth, [](float z) { return !has(z); }));
}

TEST(SheetDeshear, RowsComeOutTheWindowLaterWithTheirOwnBeltFlags) {
  for (const double max_height : {40.0, 200.0}) {
    SheetDeshear deshear(pitched(-5, max_height), kDepthJump, kWidth);
    // 200 mm at 5°: 43.7 rows of shift, and the half row of a nearest-row landing.
    const int delay = expected_delay(-5, max_height);
    ASSERT_EQ(deshear.delay(), delay);
    EXPECT_EQ(delay, max_height == 200 ? 45 : 10);
    std::vector<float> z(kWidth, kNaN);
    std::vector<std::uint8_t> belt(kWidth);
    for (int i = 0; i < delay + 5; ++i) {
      std::fill(belt.begin(), belt.end(), static_cast<std::uint8_t>(i % 2));
      belt[static_cast<std::size_t>(i % kWidth)] = 7;  // which input row it was
      EXPECT_EQ(deshear.push(z.data(), belt.data()), i >= delay) << i;
      if (i < delay) continue;
      const int k = i - delay;
      EXPECT_EQ(deshear.belt()[k % kWidth], 7) << i;
      EXPECT_EQ(deshear.belt()[(k + 1) % kWidth], k % 2) << i;
    }
  }
}

TEST(SheetDeshear, SamplesAboveTheWindowAreDroppedAndCounted) {
  SheetDeshear deshear(pitched(5, 10), kDepthJump, kWidth);
  std::vector<float> z(kWidth, kNaN);
  std::vector<std::uint8_t> belt(kWidth, 0);
  z[10] = 9.9f;   // within
  z[11] = 10.2f;  // cos 5° · 10.2 = 10.16 mm: above
  for (int i = 0; i <= deshear.delay() + 2; ++i) deshear.push(z.data(), belt.data());
  EXPECT_EQ(deshear.samples_too_high(), deshear.delay() + 3);
  EXPECT_TRUE(has(deshear.row()[10]));
  EXPECT_FALSE(has(deshear.row()[11]));
}

TEST(SheetDeshear, PushAllocatesNothing) {
  SheetDeshear deshear(pitched(5), kDepthJump, kWidth);
  const Rows input = pitched_rows(5);
  const std::uint64_t before = test::allocations_on_this_thread();
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < kRows; ++i)
      deshear.push(&input.z[static_cast<std::size_t>(i * kWidth)],
                   &input.belt[static_cast<std::size_t>(i * kWidth)]);
    for (int k = deshear.pending(); k > 0; --k) deshear.push_empty();
    deshear.clear();
  }
  EXPECT_EQ(test::allocations_on_this_thread() - before, 0u);
}

}  // namespace
}  // namespace cosmos
