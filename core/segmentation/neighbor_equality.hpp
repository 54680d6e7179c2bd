#pragma once
// Which 8-neighbours of each pixel of a row hold the same value, as bit masks (bit k for
// kNeighborOffsets[k]); the comparisons segmentation makes per row (growing edges between
// equal labels, seed pairs between different seeds, patch boundaries). The inner columns are
// compared without branches so that the compiler vectorizes them.
#include <cstddef>
#include <cstdint>

#include "core/surface/darboux_frame_field.hpp"

namespace cosmos {

// Directions 0-3 only, the neighbours visited before in raster order, of the row `own` whose
// row above is `above` (null: the first row). The rows need not be adjacent in memory, so a
// pass over rows held in rings (the real-time part builder) compares as a whole image does.
template <class T>
void equal_backward_neighbors(const T* above, const T* own, int width, std::uint8_t* equal) {
  if (width <= 0) return;
  equal[0] = above ? static_cast<std::uint8_t>((above[0] == own[0]) << 1 |
                                               (width > 1 && above[1] == own[0]) << 2)
                   : 0;
  if (!above) {
    for (int c = 1; c < width; ++c)
      equal[c] = static_cast<std::uint8_t>((own[c - 1] == own[c]) << 3);
    return;
  }
  for (int c = 1; c + 1 < width; ++c) {
    const T o = own[c];
    equal[c] = static_cast<std::uint8_t>((above[c - 1] == o) | (above[c] == o) << 1 |
                                         (above[c + 1] == o) << 2 | (own[c - 1] == o) << 3);
  }
  if (width > 1) {
    const int c = width - 1;
    equal[c] = static_cast<std::uint8_t>((above[c - 1] == own[c]) | (above[c] == own[c]) << 1 |
                                         (own[c - 1] == own[c]) << 3);
  }
}

// The same for the columns [begin, end) of the row only (equal elsewhere not written), the
// masks those columns get from the whole row's comparison.
template <class T>
void equal_backward_neighbors(const T* above, const T* own, int width, int begin, int end,
                              std::uint8_t* equal) {
  if (begin >= end) return;
  equal_backward_neighbors(above ? above + begin : nullptr, own + begin, end - begin,
                           equal + begin);
  // The range's ends compared with the neighbours beyond them.
  if (begin > 0) {
    equal[begin] |= static_cast<std::uint8_t>((own[begin - 1] == own[begin]) << 3);
    if (above) equal[begin] |= static_cast<std::uint8_t>(above[begin - 1] == own[begin]);
  }
  if (end < width && above)
    equal[end - 1] |= static_cast<std::uint8_t>((above[end] == own[end - 1]) << 2);
}

// Directions [0, kDirections) only (4: the neighbours visited before in raster order; 8: all).
// Neighbours outside the width x height grid never have their bit set.
template <int kDirections, class T>
void equal_neighbors_of_row(const T* values, int width, int height, int row, std::uint8_t* equal) {
  static_assert(kDirections == 4 || kDirections == 8);
  const T* own = values + static_cast<std::ptrdiff_t>(row) * width;
  if constexpr (kDirections == 4) {
    equal_backward_neighbors(row > 0 ? own - width : nullptr, own, width, equal);
  } else {
    auto border = [&](int column) {
      std::uint8_t mask = 0;
      for (int k = 0; k < kDirections; ++k) {
        const int c = column + kNeighborOffsets[k].column, r = row + kNeighborOffsets[k].row;
        if (c < 0 || r < 0 || c >= width || r >= height) continue;
        const T other = values[static_cast<std::ptrdiff_t>(r) * width + c];
        mask |= static_cast<std::uint8_t>((other == own[column]) << k);
      }
      return mask;
    };
    const bool inner_row = row > 0 && row + 1 < height;
    if (!inner_row || width < 3) {
      for (int column = 0; column < width; ++column) equal[column] = border(column);
      return;
    }
    const T* up = own - width;
    const T* down = own + width;
    equal[0] = border(0);
    for (int c = 1; c + 1 < width; ++c) {
      const T o = own[c];
      equal[c] = static_cast<std::uint8_t>((up[c - 1] == o) | (up[c] == o) << 1 |
                                           (up[c + 1] == o) << 2 | (own[c - 1] == o) << 3 |
                                           (own[c + 1] == o) << 4 | (down[c - 1] == o) << 5 |
                                           (down[c] == o) << 6 | (down[c + 1] == o) << 7);
    }
    equal[width - 1] = border(width - 1);
  }
}

// The columns of a row whose mask is not `value` (e.g. pixels with a neighbour of another
// patch), in increasing order, written to `columns`; returns their number. Listed without
// branches, since such pixels lie scattered along a row: looking at them from the list costs
// less than testing every column in the loop that looks at them.
inline int columns_with_mask_other_than(const std::uint8_t* masks, int width, std::uint8_t value,
                                        std::int32_t* columns) {
  int listed = 0;
  for (int column = 0; column < width; ++column) {
    columns[listed] = column;
    listed += masks[column] != value;
  }
  return listed;
}

}  // namespace cosmos
