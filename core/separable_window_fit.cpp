#include "core/separable_window_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

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
      for (int t = 0; t < kQuadricTerms; ++t) pair_taylor.push_back(taylor[t] * pair_inverse_norm_.back());
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

namespace {

// Four columns at a time (GCC vector extensions: AVX2 registers when compiled for them, SSE2
// pairs otherwise), or one (plain scalars) for the row's last columns.
using Double4 = double __attribute__((vector_size(32)));
using Float4 = float __attribute__((vector_size(16)));

template <class V>
struct Lanes;
template <>
struct Lanes<double> {
  static constexpr int kCount = 1;
  using Floats = float;
  static double load(const double* p) { return *p; }
  static float load(const float* p) { return *p; }
  static double widen(float v) { return v; }
  static float narrow(double v) { return static_cast<float>(v); }
  static double broadcast(double v) { return v; }
  static double max(double a, double b) { return a > b ? a : b; }
  static float min(float a, float b) { return a < b ? a : b; }
  static float max(float a, float b) { return a > b ? a : b; }
  static void store(float* p, float v) { *p = v; }
  static void store(double* p, double v) { *p = v; }
  static void store_complete(std::uint8_t* p, double residual, double range, double limit) {
    *p = std::isfinite(residual) && range <= limit;
  }
};
template <>
struct Lanes<Double4> {
  static constexpr int kCount = 4;
  using Floats = Float4;
  static Double4 load(const double* p) {
    Double4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static Float4 load(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static Double4 widen(Float4 v) { return __builtin_convertvector(v, Double4); }
  static Float4 narrow(Double4 v) { return __builtin_convertvector(v, Float4); }
  static Double4 broadcast(double v) { return Double4{v, v, v, v}; }
  static Double4 max(Double4 a, Double4 b) { return a > b ? a : b; }
  static Float4 min(Float4 a, Float4 b) { return a < b ? a : b; }
  static Float4 max(Float4 a, Float4 b) { return a > b ? a : b; }
  static void store(float* p, Float4 v) { std::memcpy(p, &v, sizeof v); }
  static void store(double* p, Double4 v) { std::memcpy(p, &v, sizeof v); }
  static void store_complete(std::uint8_t* p, Double4 residual, Double4 range, double limit) {
    for (int lane = 0; lane < 4; ++lane)
      p[lane] = std::isfinite(residual[lane]) && range[lane] <= limit;
  }
};

}  // namespace

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
  for (int term = 0; term < SeparableWindowFit::kQuadricTerms; ++term) {
    V q = L::broadcast(0.0);
    for (int pair = 0; pair < kPairs; ++pair)
      if (t.taylor[term][pair] != 0.0) q += t.taylor[term][pair] * dots[pair];
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

void SeparableWindowFit::fit_row(const RangeImage& image, int row, double max_depth_range_mm) {
  const int width = image.width();
  std::fill(complete_.begin(), complete_.begin() + width, 0);
  for (auto& q : quadric_float_) std::fill(q.begin(), q.begin() + width, 0.0f);
  if (row < half_ || row + half_ >= image.height()) return;
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
  if (begin >= end) return;
  switch (side_ * 10 + degree_) {
    case 32: fit_column_range<3, 2>(in, begin, end, max_depth_range_mm); break;
    case 33: fit_column_range<3, 3>(in, begin, end, max_depth_range_mm); break;
    case 52: fit_column_range<5, 2>(in, begin, end, max_depth_range_mm); break;
    case 53: fit_column_range<5, 3>(in, begin, end, max_depth_range_mm); break;
    case 72: fit_column_range<7, 2>(in, begin, end, max_depth_range_mm); break;
    case 73: fit_column_range<7, 3>(in, begin, end, max_depth_range_mm); break;
    case 92: fit_column_range<9, 2>(in, begin, end, max_depth_range_mm); break;
    case 93: fit_column_range<9, 3>(in, begin, end, max_depth_range_mm); break;
    case 112: fit_column_range<11, 2>(in, begin, end, max_depth_range_mm); break;
    default: fit_column_range<11, 3>(in, begin, end, max_depth_range_mm); break;
  }
}

}  // namespace cosmos
