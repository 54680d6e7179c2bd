#pragma once
// Two builders' rows [0, rows) compared plane by plane, bit for bit: heights, fits, frames,
// shape index, curvedness, area, validity, links and labels.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>

#include "realtime/loop/incremental_cosmos.hpp"

namespace cosmos::testing {

template <class T>
int differing_planes(const T* a, const T* b, int n) {
  return std::memcmp(a, b, static_cast<std::size_t>(n) * sizeof(T)) != 0 ? 1 : 0;
}

inline void expect_identical_rows(const IncrementalCosmos& a, const IncrementalCosmos& b,
                                  int rows) {
  ASSERT_LE(rows, a.rows());
  ASSERT_LE(rows, b.rows());
  int differences = 0;
  for (int r = 0; r < rows; ++r) {
    const PartRow x = a.row(r), y = b.row(r);
    ASSERT_EQ(x.column_begin, y.column_begin) << r;
    ASSERT_EQ(x.column_end, y.column_end) << r;
    const int n = x.column_end - x.column_begin;
    differences +=
        differing_planes(x.z_mm, y.z_mm, n) + differing_planes(x.fitted_z_mm, y.fitted_z_mm, n) +
        differing_planes(x.valid, y.valid, n) + differing_planes(x.same_side, y.same_side, n) +
        differing_planes(x.label, y.label, n) + differing_planes(x.shape_index, y.shape_index, n) +
        differing_planes(x.curvedness_per_mm, y.curvedness_per_mm, n) +
        differing_planes(x.area_mm2, y.area_mm2, n);
    for (int c = 0; c < kFrameComponents; ++c)
      differences += differing_planes(x.frame[c], y.frame[c], n);
  }
  EXPECT_EQ(differences, 0);
}

}  // namespace cosmos::testing
