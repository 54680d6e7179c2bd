#include "core/separable_window_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cosmos {

SeparableWindowFit::SeparableWindowFit(int half_window, int degree, int max_width)
    : half_(half_window),
      side_(2 * half_window + 1),
      degree_(degree),
      filters_(degree + 2),
      max_width_(std::max(max_width, 1)),
      polynomial_(static_cast<std::size_t>(degree + 1) * side_, 0.0),
      norm_(degree + 1, 0.0),
      monomial_(static_cast<std::size_t>(degree + 1) * (degree + 1), 0.0),
      slot_row_(side_, -1),
      slot_columns_(static_cast<std::size_t>(side_), {0, 0}),
      filtered_(static_cast<std::size_t>(side_) * filters_ * max_width_, 0.0),
      row_min_(static_cast<std::size_t>(side_) * max_width_, 0.0f),
      row_max_(static_cast<std::size_t>(side_) * max_width_, 0.0f),
      residual_(max_width_, 0.0),
      dot_(),
      range_low_(max_width_, 0.0f),
      range_high_(max_width_, 0.0f),
      complete_(max_width_, 0) {
  for (auto& q : quadric_) q.assign(max_width_, 0.0);
  for (auto& q : quadric_float_) q.assign(max_width_, 0.0f);
  // Gram-Schmidt of 1, u, u^2, ... over the window's sample positions.
  for (int i = 0; i <= degree_; ++i) {
    monomial_[i * (degree_ + 1) + i] = 1.0;
    for (int k = 0; k < side_; ++k) polynomial_[i * side_ + k] = std::pow(k - half_, i);
    for (int j = 0; j < i; ++j) {
      double dot = 0;
      for (int k = 0; k < side_; ++k)
        dot += polynomial_[i * side_ + k] * polynomial_[j * side_ + k];
      const double factor = dot / norm_[j];
      for (int k = 0; k < side_; ++k)
        polynomial_[i * side_ + k] -= factor * polynomial_[j * side_ + k];
      for (int m = 0; m <= degree_; ++m)
        monomial_[i * (degree_ + 1) + m] -= factor * monomial_[j * (degree_ + 1) + m];
    }
    for (int k = 0; k < side_; ++k)
      norm_[i] += polynomial_[i * side_ + k] * polynomial_[i * side_ + k];
  }
  // The centre's Taylor terms (z, z_u, z_v, z_uu/2, z_uv, z_vv/2) from the low-order monomial
  // coefficients of p_i(u) p_j(v); on a symmetric window most of them vanish.
  const int stride = degree_ + 1;
  for (int i = 0; i <= degree_; ++i) {
    for (int j = 0; i + j <= degree_; ++j) {
      const int pair = static_cast<int>(pairs_.size());
      pairs_.push_back({i, j});
      const double* mi = &monomial_[i * stride];
      const double* mj = &monomial_[j * stride];
      const double taylor[kQuadricTerms] = {mi[0] * mj[0], mi[1] * mj[0],
                                            mi[0] * mj[1], degree_ >= 2 ? mi[2] * mj[0] : 0.0,
                                            mi[1] * mj[1], degree_ >= 2 ? mi[0] * mj[2] : 0.0};
      const double inverse_norm = 1.0 / (norm_[i] * norm_[j]);
      for (int t = 0; t < kQuadricTerms; ++t)
        if (taylor[t] != 0.0) taylor_terms_.push_back({pair, t, taylor[t] * inverse_norm});
    }
  }
  dot_.assign(pairs_.size() * static_cast<std::size_t>(max_width_), 0.0);
}

void SeparableWindowFit::reset() { std::fill(slot_row_.begin(), slot_row_.end(), -1); }

void SeparableWindowFit::filter_image_row(const RangeImage& image, int image_row, int slot) {
  slot_row_[slot] = image_row;
  const int width = image.width();
  const float* z = image.z_mm.row(image_row);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // A part rarely fills the row: only windows within its first and last sample can be
  // complete (a NaN inside the span still makes its windows NaN, as before).
  int first = 0, last = width;
  while (first < last && std::isnan(z[first])) ++first;
  while (last > first && std::isnan(z[last - 1])) --last;
  const int begin = std::max(half_, first + half_), end = std::min(width - half_, last - half_);
  slot_columns_[static_cast<std::size_t>(slot)] = {begin, std::max(begin, end)};
  float* __restrict low = &row_min_[static_cast<std::size_t>(slot) * max_width_];
  float* __restrict high = &row_max_[static_cast<std::size_t>(slot) * max_width_];
  for (int f = 0; f < filters_; ++f) {
    double* __restrict out = &filtered(slot, f, 0);
    std::fill(out, out + width, nan);  // columns whose window leaves the image or the data
    for (int c = begin; c < end; ++c) out[c] = 0.0;
  }
  for (int c = begin; c < end; ++c) {
    low[c] = std::numeric_limits<float>::infinity();
    high[c] = -std::numeric_limits<float>::infinity();
  }
  // Tap by tap over the columns (column-inner loops vectorize); NaN samples make NaN sums.
  for (int k = 0; k < side_; ++k) {
    const float* __restrict shifted = z + k - half_;
    for (int f = 0; f <= degree_; ++f) {
      double* __restrict out = &filtered(slot, f, 0);
      const double weight = polynomial_[f * side_ + k];
      for (int c = begin; c < end; ++c) out[c] += weight * static_cast<double>(shifted[c]);
    }
    double* __restrict squares = &filtered(slot, filters_ - 1, 0);
    for (int c = begin; c < end; ++c) {
      const double value = shifted[c];
      squares[c] += value * value;
      low[c] = std::min(low[c], shifted[c]);
      high[c] = std::max(high[c], shifted[c]);
    }
  }
}

void SeparableWindowFit::fit_row(const RangeImage& image, int row, double max_depth_range_mm) {
  const int width = image.width();
  std::fill(complete_.begin(), complete_.begin() + width, 0);
  for (auto& q : quadric_) std::fill(q.begin(), q.begin() + width, 0.0);
  for (auto& q : quadric_float_) std::fill(q.begin(), q.begin() + width, 0.0f);
  if (row < half_ || row + half_ >= image.height()) return;
  int slots[kMaxSide];
  for (int dv = -half_; dv <= half_; ++dv) {
    const int image_row = row + dv;
    slots[dv + half_] = image_row % side_;
    if (slot_row_[slots[dv + half_]] != image_row)
      filter_image_row(image, image_row, slots[dv + half_]);
  }
  // Column-inner loops over the columns every window row can complete, so the compiler
  // vectorizes them; the rest stay incomplete (complete_ 0, quadric 0).
  int begin = half_, end = width - half_;
  for (int k = 0; k < side_; ++k) {
    begin = std::max(begin, slot_columns_[static_cast<std::size_t>(slots[k])][0]);
    end = std::min(end, slot_columns_[static_cast<std::size_t>(slots[k])][1]);
  }
  if (begin >= end) return;
  double* __restrict squares = residual_.data();
  float* __restrict low = range_low_.data();
  float* __restrict high = range_high_.data();
  for (int c = begin; c < end; ++c) {
    squares[c] = 0.0;
    low[c] = std::numeric_limits<float>::infinity();
    high[c] = -std::numeric_limits<float>::infinity();
  }
  for (int k = 0; k < side_; ++k) {
    const double* __restrict row_squares = &filtered(slots[k], filters_ - 1, 0);
    const float* __restrict row_low = &row_min_[static_cast<std::size_t>(slots[k]) * max_width_];
    const float* __restrict row_high = &row_max_[static_cast<std::size_t>(slots[k]) * max_width_];
    for (int c = begin; c < end; ++c) {
      squares[c] += row_squares[c];
      low[c] = std::min(low[c], row_low[c]);
      high[c] = std::max(high[c], row_high[c]);
    }
  }
  // a_ij = <z, p_i(u) p_j(v)> / (|p_i|^2 |p_j|^2) for i + j <= degree; the residual is what
  // the fit does not explain, |z|^2 - sum a_ij <z, p_i p_j>; the Taylor terms at the centre
  // are the sparse combinations of the a_ij listed in taylor_terms_.
  for (std::size_t pair = 0; pair < pairs_.size(); ++pair) {
    const auto [i, j] = pairs_[pair];
    double* __restrict dot = &dot_[pair * static_cast<std::size_t>(max_width_)];
    for (int c = begin; c < end; ++c) dot[c] = 0.0;
    for (int k = 0; k < side_; ++k) {
      const double weight = polynomial_[j * side_ + k];
      const double* __restrict f = &filtered(slots[k], i, 0);
      for (int c = begin; c < end; ++c) dot[c] += weight * f[c];
    }
    const double inverse_norm = 1.0 / (norm_[i] * norm_[j]);
    for (int c = begin; c < end; ++c) squares[c] -= inverse_norm * dot[c] * dot[c];
  }
  for (const TaylorTerm& term : taylor_terms_) {
    const double* __restrict dot = &dot_[term.pair * static_cast<std::size_t>(max_width_)];
    double* __restrict q = quadric_[term.quadric_term].data();
    for (int c = begin; c < end; ++c) q[c] += term.coefficient * dot[c];
  }
  for (int t = 0; t < kQuadricTerms; ++t) {
    const double* __restrict q = quadric_[t].data();
    float* __restrict q_float = quadric_float_[t].data();
    for (int c = begin; c < end; ++c) q_float[c] = static_cast<float>(q[c]);
  }
  for (int c = begin; c < end; ++c) {
    complete_[c] = std::isfinite(squares[c]) && high[c] - low[c] <= max_depth_range_mm;
    squares[c] = std::max(0.0, squares[c]);
  }
}

}  // namespace cosmos
