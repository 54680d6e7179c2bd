#pragma once
// Shape spectrum of a view (§3.2.3, §3.5.4): area-weighted histogram of per-pixel shape index,
// normalized by the visible area, with a separate planar bin; its moments (Eqs. 4.1-4.2),
// the planar fraction as 11th feature (§4.5.5) and the dissimilarity of Eq. 4.3.
#include <array>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/surface/shape_index.hpp"

namespace cosmos {

inline constexpr int kSpectrumMoments = 10;
using MomentVector = std::array<double, kSpectrumMoments + 1>;  // m1..m10, planar fraction

struct ShapeSpectrum {
  double bin_width = 0.005;
  std::vector<double> bins;    // fraction of the visible area per S_I bin over [0, 1]
  double planar_fraction = 0;  // fraction of the visible area that is planar (S_I = 2.0)
  double visible_area_mm2 = 0;
};

// Accumulates area into a spectrum one pixel at a time, so the real-time loop can feed it
// row by row; finish() normalizes.
class ShapeSpectrumAccumulator {
 public:
  explicit ShapeSpectrumAccumulator(const SpectrumParameters& parameters);
  void add(SurfaceLabel label, float shape_index, float area_mm2);
  void add_row(const ShapeIndexField& field, int row);
  void clear();
  ShapeSpectrum finish() const;

 private:
  double bin_width_;
  std::vector<double> area_per_bin_mm2_;
  double planar_area_mm2_ = 0;
};

ShapeSpectrum compute_shape_spectrum(const ShapeIndexField& field,
                                     const SpectrumParameters& parameters);

// Eqs. 4.1-4.2 over the non-planar spectrum (renormalized to unit mass, §4.4), bin centres
// as h; element 10 is the planar fraction (§4.5.5).
MomentVector spectrum_moments(const ShapeSpectrum& spectrum);

// Eq. 4.3: sum of squared differences of the ten moments.
double spectral_dissimilarity(const MomentVector& a, const MomentVector& b);

}  // namespace cosmos
