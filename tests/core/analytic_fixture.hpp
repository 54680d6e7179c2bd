#pragma once
// Shared helpers for core tests on analytic surfaces: run the pipeline and collect the
// "interior" pixels — 2 px away from borders and holes, normal within 60 degrees of the
// viewing direction — where the estimates are compared with the closed-form truth.
#include <algorithm>
#include <vector>

#include "core/representation/cosmos_pipeline.hpp"
#include "sim/analytic_surface.hpp"

namespace cosmos::testing {

inline AnalyticSurface analytic(AnalyticShape shape, double noise_mm = 0.0,
                                double rotate_deg = 0.0) {
  AnalyticSurfaceSpec spec;
  spec.shape = shape;
  spec.noise_mm = noise_mm;
  spec.rotate_deg = rotate_deg;
  spec.seed = 11;
  return make_analytic_surface(spec);
}

inline ViewAnalysis analyze(const AnalyticSurface& surface, int smoothing_iterations = 15) {
  CosmosParameters parameters;
  parameters.smoothing.iterations = smoothing_iterations;
  return analyze_view(surface.range, parameters);
}

inline bool is_interior(const AnalyticSurface& surface, int column, int row) {
  const auto& truth = surface.truth(column, row);
  if (!truth.valid || truth.normal.z() < 0.5f) return false;
  for (int dr = -2; dr <= 2; ++dr)
    for (int dc = -2; dc <= 2; ++dc)
      if (!surface.range.has_data(column + dc, row + dr)) return false;
  return true;
}

// Calls visit(pixel index, truth) for every interior pixel.
template <class Visit>
void for_each_interior(const AnalyticSurface& surface, Visit&& visit) {
  for (int row = 0; row < surface.range.height(); ++row)
    for (int column = 0; column < surface.range.width(); ++column)
      if (is_interior(surface, column, row))
        visit(surface.truth.index(column, row), surface.truth(column, row));
}

inline double fraction_true(const std::vector<bool>& flags) {
  if (flags.empty()) return 0.0;
  return static_cast<double>(std::count(flags.begin(), flags.end(), true)) / flags.size();
}

inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace cosmos::testing
