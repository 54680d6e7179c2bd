#pragma once
// Synthetic laser-stripe frames with a known sub-pixel centre per column, for the stripe
// extraction and triangulation tests and the extraction benchmark. Deterministic: every
// random draw comes from the seeded generator.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

namespace cosmos::test {

struct StripeNoise {
  double additive_sigma = 0.0;      // grey levels, read noise and background
  double speckle_sigma = 0.0;       // relative, multiplicative per pixel (laser speckle)
  double electrons_per_grey = 0.0;  // shot noise: Poisson in electrons; 0 = off
};

struct StripeShape {
  double sigma_px = 2.0;     // Gaussian width across the stripe (rows)
  double amplitude = 200.0;  // peak intensity before clipping (grey levels)
};

// Frame of `rows` rows and centre_row_px.size() columns of Pixel (uint8_t or uint16_t):
// column c holds A·exp(−(r − centre)² / 2σ²) point-sampled at pixel centres (rows), then
// noise, rounded and clipped to the type's range. A NaN centre leaves the column dark
// (noise only).
template <class Pixel>
cv::Mat render_stripe(const std::vector<double>& centre_row_px, int rows, const StripeShape& shape,
                      const StripeNoise& noise = {}, std::uint32_t seed = 1) {
  const int columns = static_cast<int>(centre_row_px.size());
  cv::Mat frame(rows, columns, cv::DataType<Pixel>::type);
  std::mt19937 rng(seed);
  std::normal_distribution<double> unit_normal(0.0, 1.0);
  const double max_value = std::numeric_limits<Pixel>::max();
  const double inverse_two_sigma2 = 1.0 / (2.0 * shape.sigma_px * shape.sigma_px);
  for (int r = 0; r < rows; ++r) {
    Pixel* row = frame.ptr<Pixel>(r);
    for (int c = 0; c < columns; ++c) {
      const double centre = centre_row_px[static_cast<std::size_t>(c)];
      double value = 0.0;
      if (!std::isnan(centre)) {
        const double d = r - centre;
        value = shape.amplitude * std::exp(-d * d * inverse_two_sigma2);
      }
      if (noise.speckle_sigma > 0.0)
        value *= std::max(0.0, 1.0 + noise.speckle_sigma * unit_normal(rng));
      if (noise.electrons_per_grey > 0.0 && value > 0.0) {
        std::poisson_distribution<long> electrons(value * noise.electrons_per_grey);
        value = static_cast<double>(electrons(rng)) / noise.electrons_per_grey;
      }
      if (noise.additive_sigma > 0.0) value += noise.additive_sigma * unit_normal(rng);
      row[c] = static_cast<Pixel>(std::clamp(std::round(value), 0.0, max_value));
    }
  }
  return frame;
}

// A stripe that wanders smoothly over the rows and, with an irrational step per column,
// sweeps every fractional offset: centre(c) = mid + swing·sin(2πc / 400) + frac(0.618·c).
inline std::vector<double> wandering_centres(int columns, double mid_row, double swing_rows) {
  std::vector<double> centres(static_cast<std::size_t>(columns));
  for (int c = 0; c < columns; ++c) {
    const double fraction = std::fmod(0.6180339887 * c, 1.0);
    centres[static_cast<std::size_t>(c)] =
        mid_row + swing_rows * std::sin(2.0 * 3.14159265358979 * c / 400.0) + fraction;
  }
  return centres;
}

}  // namespace cosmos::test
