#include "core/surface/separable_window_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/surface/window_lanes.hpp"

namespace cosmos {

using window_lanes::Double4;
using window_lanes::Lanes;

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

      complete_(max_width_, 0) {
  if (side_ < 3 || side_ > kMaxSide || (degree_ != 2 && degree_ != 3))
    throw std::invalid_argument("SeparableWindowFit: window side must be 3..11 and degree 2 or 3");
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
  std::vector<double> pair_taylor;  // [pair][term]
  for (int i = 0; i <= degree_; ++i) {
    for (int j = 0; i + j <= degree_; ++j) {
      const double* mi = &monomial_[i * stride];
      const double* mj = &monomial_[j * stride];
      const double taylor[kQuadricTerms] = {mi[0] * mj[0], mi[1] * mj[0],
                                            mi[0] * mj[1], degree_ >= 2 ? mi[2] * mj[0] : 0.0,
                                            mi[1] * mj[1], degree_ >= 2 ? mi[0] * mj[2] : 0.0};
      pair_inverse_norm_.push_back(1.0 / (norm_[i] * norm_[j]));
      for (int t = 0; t < kQuadricTerms; ++t)
        pair_taylor.push_back(taylor[t] * pair_inverse_norm_.back());
    }
  }
  // Dense table [term][pair] for the column pass.
  const auto pairs = pair_inverse_norm_.size();
  taylor_table_.assign(kQuadricTerms * pairs, 0.0);
  for (std::size_t pair = 0; pair < pairs; ++pair)
    for (int t = 0; t < kQuadricTerms; ++t)
      taylor_table_[t * pairs + pair] = pair_taylor[pair * kQuadricTerms + t];
}

void SeparableWindowFit::reset() { std::fill(slot_row_.begin(), slot_row_.end(), -1); }

// The column pass's constants and outputs, copied out of the members so that the compiler
// sees they do not alias the outputs (and keeps the constants in registers).
template <int Side, int Degree>
struct ColumnPassTables {
  static constexpr int kPairs = (Degree + 1) * (Degree + 2) / 2;
  double polynomial[Degree + 1][Side];
  double inverse_norm[kPairs];
  double taylor[SeparableWindowFit::kQuadricTerms][kPairs];
  float* quadric[SeparableWindowFit::kQuadricTerms];
  double* residual;
  std::uint8_t* complete;
};

namespace {

// The column pass of one row for columns [c, c + lanes): the window's row filters combined by
// the column polynomials into the pair dot products <z, p_i(u) p_j(v)>, all in registers;
// from them the residual and the centre's Taylor terms.
template <int Side, int Degree, class V>
[[gnu::always_inline]] inline void fit_columns(const SeparableWindowFit::ColumnPassInputs& in,
                                               const ColumnPassTables<Side, Degree>& t, int c,
                                               double max_range_mm) {
  using L = Lanes<V>;
  constexpr int kFilters = Degree + 1;
  constexpr int kPairs = ColumnPassTables<Side, Degree>::kPairs;
  V dots[kPairs];
  for (V& d : dots) d = L::broadcast(0.0);
  V squares = L::broadcast(0.0);
  auto low = L::load(in.low[0] + c), high = L::load(in.high[0] + c);
  for (int k = 0; k < Side; ++k) {
    V f[kFilters];
    for (int i = 0; i < kFilters; ++i) f[i] = L::load(in.filtered[k][i] + c);
    squares += L::load(in.filtered[k][kFilters] + c);
    if (k > 0) {
      low = L::min(low, L::load(in.low[k] + c));
      high = L::max(high, L::load(in.high[k] + c));
    }
    int pair = 0;
    for (int i = 0; i <= Degree; ++i)
      for (int j = 0; i + j <= Degree; ++j, ++pair) dots[pair] += t.polynomial[j][k] * f[i];
  }
  V residual = squares;
  for (int pair = 0; pair < kPairs; ++pair)
    residual -= t.inverse_norm[pair] * dots[pair] * dots[pair];
  // On the symmetric window p_i has the parity of i and degree i, so the u^a coefficient of
  // p_i can be nonzero only for a <= i of i's parity: after unrolling, the zero products of
  // the table are known at compile time and dropped.
  constexpr int kOrders[SeparableWindowFit::kQuadricTerms][2] = {{0, 0}, {1, 0}, {0, 1},
                                                                 {2, 0}, {1, 1}, {0, 2}};
#pragma GCC unroll 6
  for (int term = 0; term < SeparableWindowFit::kQuadricTerms; ++term) {
    const int a = kOrders[term][0], b = kOrders[term][1];
    V q = L::broadcast(0.0);
    int pair = 0;
#pragma GCC unroll 4
    for (int i = 0; i <= Degree; ++i) {
#pragma GCC unroll 4
      for (int j = 0; i + j <= Degree; ++j, ++pair)
        if (a <= i && (i - a) % 2 == 0 && b <= j && (j - b) % 2 == 0)
          q += t.taylor[term][pair] * dots[pair];
    }
    L::store(t.quadric[term] + c, L::narrow(q));
  }
  L::store(t.residual + c, L::max(residual, L::broadcast(0.0)));
  L::store_complete(t.complete + c, residual, L::widen(high - low), max_range_mm);
}

}  // namespace

template <int Side, int Degree>
void SeparableWindowFit::fit_column_range(const ColumnPassInputs& in, int begin, int end,
                                          double max_range_mm) {
  ColumnPassTables<Side, Degree> t;
  constexpr int kPairs = ColumnPassTables<Side, Degree>::kPairs;
  for (int i = 0; i <= Degree; ++i)
    for (int k = 0; k < Side; ++k) t.polynomial[i][k] = polynomial_[i * Side + k];
  for (int pair = 0; pair < kPairs; ++pair) {
    t.inverse_norm[pair] = pair_inverse_norm_[pair];
    for (int term = 0; term < kQuadricTerms; ++term)
      t.taylor[term][pair] = taylor_table_[term * kPairs + pair];
  }
  for (int term = 0; term < kQuadricTerms; ++term) t.quadric[term] = quadric_float_[term].data();
  t.residual = residual_.data();
  t.complete = complete_.data();
  int c = begin;
  for (; c + 4 <= end; c += 4) fit_columns<Side, Degree, Double4>(in, t, c, max_range_mm);
  for (; c < end; ++c) fit_columns<Side, Degree, double>(in, t, c, max_range_mm);
}

namespace {

// The row filters of one image row for columns [c, c + lanes): the degree + 1 polynomial
// filters and the sum of squares over the window's columns, and the depth range.
template <int Side, int Degree, class V>
[[gnu::always_inline]] inline void filter_columns(const float* z,
                                                  const double (&polynomial)[Degree + 1][Side],
                                                  double* const* out, float* low, float* high,
                                                  int c) {
  using L = Lanes<V>;
  constexpr int kHalf = Side / 2;
  V filters[Degree + 1];
  for (V& f : filters) f = L::broadcast(0.0);
  V squares = L::broadcast(0.0);
  auto lowest = L::load(z + c - kHalf), highest = lowest;
  for (int k = 0; k < Side; ++k) {
    const auto samples = L::load(z + c + k - kHalf);
    const V value = L::widen(samples);
    for (int i = 0; i <= Degree; ++i) filters[i] += polynomial[i][k] * value;
    squares += value * value;
    lowest = L::min(lowest, samples);
    highest = L::max(highest, samples);
  }
  for (int i = 0; i <= Degree; ++i) L::store(out[i] + c, filters[i]);
  L::store(out[Degree + 1] + c, squares);
  L::store(low + c, lowest);
  L::store(high + c, highest);
}

}  // namespace

template <int Side, int Degree>
void SeparableWindowFit::filter_column_range(const float* z, int slot, int begin, int end) {
  double polynomial[Degree + 1][Side];
  for (int i = 0; i <= Degree; ++i)
    for (int k = 0; k < Side; ++k) polynomial[i][k] = polynomial_[i * Side + k];
  double* out[Degree + 2];
  for (int f = 0; f < Degree + 2; ++f) out[f] = &filtered(slot, f, 0);
  float* low = &row_min_[static_cast<std::size_t>(slot) * max_width_];
  float* high = &row_max_[static_cast<std::size_t>(slot) * max_width_];
  int c = begin;
  for (; c + 4 <= end; c += 4)
    filter_columns<Side, Degree, Double4>(z, polynomial, out, low, high, c);
  for (; c < end; ++c) filter_columns<Side, Degree, double>(z, polynomial, out, low, high, c);
}

// Calls run.template operator()<Side, Degree>() for the window's shape.
template <class Run>
void SeparableWindowFit::with_window_shape(Run&& run) const {
  switch (side_ * 10 + degree_) {
    case 32:
      run.template operator()<3, 2>();
      break;
    case 33:
      run.template operator()<3, 3>();
      break;
    case 52:
      run.template operator()<5, 2>();
      break;
    case 53:
      run.template operator()<5, 3>();
      break;
    case 72:
      run.template operator()<7, 2>();
      break;
    case 73:
      run.template operator()<7, 3>();
      break;
    case 92:
      run.template operator()<9, 2>();
      break;
    case 93:
      run.template operator()<9, 3>();
      break;
    case 112:
      run.template operator()<11, 2>();
      break;
    default:
      run.template operator()<11, 3>();
      break;
  }
}

void SeparableWindowFit::filter_image_row(const RangeImage& image, int image_row, int slot) {
  slot_row_[slot] = image_row;
  const int width = image.width();
  const float* z = image.z_mm.row(image_row);
  // A part rarely fills the row: only windows within its first and last sample can be
  // complete (a NaN inside the span still makes its windows NaN, as before).
  int first = 0, last = width;
  while (first < last && std::isnan(z[first])) ++first;
  while (last > first && std::isnan(z[last - 1])) --last;
  const int begin = std::min(width, std::max(half_, first + half_));
  const int end = std::max(begin, std::min(width - half_, last - half_));
  slot_columns_[static_cast<std::size_t>(slot)] = {begin, end};
  // Columns whose window leaves the image or the data: NaN (never complete).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int f = 0; f < filters_; ++f) {
    double* out = &filtered(slot, f, 0);
    std::fill(out, out + begin, nan);
    std::fill(out + end, out + width, nan);
  }
  with_window_shape(
      [&]<int Side, int Degree>() { filter_column_range<Side, Degree>(z, slot, begin, end); });
}

void SeparableWindowFit::fit_row(const RangeImage& image, int row, double max_depth_range_mm) {
  const int width = image.width();
  // Columns outside [begin, end) are incomplete, with quadric 0; the column pass writes the rest.
  const auto clear_outside = [&](int begin, int end) {
    for (const auto& [from, to] : {std::pair{0, begin}, std::pair{end, width}}) {
      std::fill(complete_.begin() + from, complete_.begin() + to, 0);
      for (auto& q : quadric_float_) std::fill(q.begin() + from, q.begin() + to, 0.0f);
    }
  };
  if (row < half_ || row + half_ >= image.height()) {
    clear_outside(width, width);
    return;
  }
  int slots[kMaxSide];
  for (int dv = -half_; dv <= half_; ++dv) {
    const int image_row = row + dv;
    slots[dv + half_] = image_row % side_;
    if (slot_row_[slots[dv + half_]] != image_row)
      filter_image_row(image, image_row, slots[dv + half_]);
  }
  // Only the columns every window row can complete; the rest stay incomplete (quadric 0).
  int begin = half_, end = width - half_;
  ColumnPassInputs in;
  for (int k = 0; k < side_; ++k) {
    const auto slot = static_cast<std::size_t>(slots[k]);
    begin = std::max(begin, slot_columns_[slot][0]);
    end = std::min(end, slot_columns_[slot][1]);
    for (int f = 0; f < filters_; ++f) in.filtered[k][f] = &filtered(slots[k], f, 0);
    in.low[k] = &row_min_[slot * max_width_];
    in.high[k] = &row_max_[slot * max_width_];
  }
  end = std::max(begin, end);
  clear_outside(begin, end);
  if (begin == end) return;
  with_window_shape([&]<int Side, int Degree>() {
    fit_column_range<Side, Degree>(in, begin, end, max_depth_range_mm);
  });
}

}  // namespace cosmos
