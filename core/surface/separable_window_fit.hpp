#pragma once
// The least-squares polynomial fit of §3.5.1 over complete windows, computed separably.
// On a square window the product polynomials p_i(u) p_j(v) of the discrete orthogonal
// polynomials on {-h..h} are orthogonal, so every fit coefficient is a row filter followed by
// a column filter: about 15 multiply-adds per pixel for a 5x5 bicubic instead of 250, and
// the fit's residual comes for free. Row filters are cached in a ring of 2h+1 image rows, so
// fitting the rows of an image in order filters each image row once (the real-time loop fits
// one row per profile).
#include <array>
#include <cstdint>
#include <vector>

#include "core/range_image.hpp"

namespace cosmos {

class SeparableWindowFit {
 public:
  static constexpr int kQuadricTerms = 6;  // z, z_u, z_v, z_uu/2, z_uv, z_vv/2 (pixel units)
  static constexpr int kMaxSide = 11;
  static constexpr int kMaxDegree = 3;

  SeparableWindowFit(int half_window, int degree, int max_width);

  // Fits the centred window of every pixel of `row`. A pixel is `complete` when its whole
  // window has data spanning at most max_depth_range_mm; only then are its coefficients
  // (relative to nothing: absolute z) and residual meaningful.
  void fit_row(const RangeImage& image, int row, double max_depth_range_mm);
  // Forgets the cached row filters (a new image reuses the buffers).
  void reset();

  // The Taylor terms in float (what the frames are computed in); 0 where incomplete.
  const float* quadric(int term) const { return quadric_float_[term].data(); }
  const double* residual_sum_of_squares() const { return residual_.data(); }
  const std::uint8_t* complete() const { return complete_.data(); }

  // Per window row k (0..side-1): its row filters (degree + 1 polynomials, then the sum of
  // squares) and the depth range of its window rows.
  struct ColumnPassInputs {
    const double* filtered[kMaxSide][kMaxDegree + 2];
    const float* low[kMaxSide];
    const float* high[kMaxSide];
  };

 private:
  void filter_image_row(const RangeImage& image, int image_row, int slot);
  template <int Side, int Degree>
  void fit_column_range(const ColumnPassInputs& in, int begin, int end, double max_range_mm);
  template <int Side, int Degree>
  void filter_column_range(const float* z, int slot, int begin, int end);
  template <class Run>
  void with_window_shape(Run&& run) const;
  double& filtered(int slot, int filter, int column) {
    return filtered_[(static_cast<std::size_t>(slot) * filters_ + filter) * max_width_ + column];
  }

  int half_;
  int side_;
  int degree_;
  int filters_;  // degree + 1 polynomial filters, then the sum of squares
  int max_width_;
  std::vector<double> polynomial_;  // p_i(u) at u = -h..h, row per degree
  std::vector<double> norm_;        // sum over u of p_i(u)^2
  std::vector<double> monomial_;    // monomial coefficients of p_i, row per degree
  std::vector<int> slot_row_;       // image row held by each ring slot (-1: none)
  // Per slot: the columns whose window lies within the row's data, [first, last); outside
  // them the filtered values are NaN and nothing else is computed.
  std::vector<std::array<int, 2>> slot_columns_;
  std::vector<double> filtered_;          // slot x filter x column
  std::vector<float> row_min_, row_max_;  // slot x column: depth range of the window's row
  // Per coefficient pair (i, j), i + j <= degree, in order: 1 / (|p_i|^2 |p_j|^2); and the
  // centre's Taylor terms as [term][pair] multiples of the pair dot products.
  std::vector<double> pair_inverse_norm_;
  std::vector<double> taylor_table_;
  std::vector<float> quadric_float_[kQuadricTerms];
  std::vector<double> residual_;
  std::vector<std::uint8_t> complete_;
};

}  // namespace cosmos
