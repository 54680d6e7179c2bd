#include "core/representation/shape_spectrum.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

ShapeSpectrumAccumulator::ShapeSpectrumAccumulator(const SpectrumParameters& parameters)
    : bin_width_(parameters.bin_width),
      area_per_bin_mm2_(static_cast<std::size_t>(std::lround(1.0 / parameters.bin_width)), 0.0) {}

void ShapeSpectrumAccumulator::add(SurfaceLabel label, float shape_index, float area_mm2) {
  if (label == SurfaceLabel::kPlanar) {
    planar_area_mm2_ += area_mm2;
  } else if (label == SurfaceLabel::kCurved) {
    // Bin k is [k w, (k+1) w); S_I = 1 belongs to the last bin (§3.2.3).
    const auto last = static_cast<long>(area_per_bin_mm2_.size()) - 1;
    const long bin = std::clamp(static_cast<long>(shape_index / bin_width_), 0L, last);
    area_per_bin_mm2_[bin] += area_mm2;
  }
}

void ShapeSpectrumAccumulator::clear() {
  std::fill(area_per_bin_mm2_.begin(), area_per_bin_mm2_.end(), 0.0);
  planar_area_mm2_ = 0;
}

void ShapeSpectrumAccumulator::add_row(const ShapeIndexField& field, int row) {
  for (int column = 0; column < field.width(); ++column) {
    const std::size_t i = field.label.index(column, row);
    add(field.label[i], field.shape_index[i], field.area_mm2[i]);
  }
}

ShapeSpectrum ShapeSpectrumAccumulator::finish() const {
  ShapeSpectrum spectrum;
  spectrum.bin_width = bin_width_;
  double total = planar_area_mm2_;
  for (double area : area_per_bin_mm2_) total += area;
  spectrum.visible_area_mm2 = total;
  spectrum.bins.assign(area_per_bin_mm2_.size(), 0.0);
  if (total <= 0) return spectrum;
  for (std::size_t k = 0; k < area_per_bin_mm2_.size(); ++k)
    spectrum.bins[k] = area_per_bin_mm2_[k] / total;
  spectrum.planar_fraction = planar_area_mm2_ / total;
  return spectrum;
}

ShapeSpectrum compute_shape_spectrum(const ShapeIndexField& field,
                                     const SpectrumParameters& parameters) {
  ShapeSpectrumAccumulator accumulator(parameters);
  for (int row = 0; row < field.height(); ++row) accumulator.add_row(field, row);
  return accumulator.finish();
}

MomentVector spectrum_moments(const ShapeSpectrum& spectrum) {
  MomentVector moments{};
  moments[kSpectrumMoments] = spectrum.planar_fraction;  // §4.5.5
  double curved_mass = 0;
  for (double b : spectrum.bins) curved_mass += b;
  if (curved_mass <= 0) return moments;
  const auto h = [&](std::size_t k) { return (static_cast<double>(k) + 0.5) * spectrum.bin_width; };
  double mean = 0;
  for (std::size_t k = 0; k < spectrum.bins.size(); ++k)
    mean += h(k) * spectrum.bins[k] / curved_mass;
  moments[0] = mean;  // Eq. 4.1
  for (std::size_t k = 0; k < spectrum.bins.size(); ++k) {
    const double weight = spectrum.bins[k] / curved_mass;
    const double deviation = h(k) - mean;
    double power = deviation;
    for (int p = 2; p <= kSpectrumMoments; ++p) {
      power *= deviation;
      moments[p - 1] += power * weight;  // Eq. 4.2
    }
  }
  return moments;
}

double spectral_dissimilarity(const MomentVector& a, const MomentVector& b) {
  double sum = 0;
  for (int l = 0; l < kSpectrumMoments; ++l) sum += (a[l] - b[l]) * (a[l] - b[l]);  // Eq. 4.3
  return sum;
}

}  // namespace cosmos
