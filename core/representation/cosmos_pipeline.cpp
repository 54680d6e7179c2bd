#include "core/representation/cosmos_pipeline.hpp"

#include "core/surface/curvature_consistency.hpp"
#include "core/surface/local_surface_fit.hpp"

namespace cosmos {

namespace {

// Chapter 3 from the fitted frames on.
void analyze_fitted_view(const RangeImage& image, const CosmosParameters& parameters,
                         ViewAnalysis& analysis) {
  smooth_curvatures(analysis.frames, image.pixel_size_x_mm, image.pixel_size_y_mm,
                    parameters.smoothing);
  analysis.field = classify_surface(analysis.frames, image.pixel_size_x_mm, image.pixel_size_y_mm,
                                    parameters.shape_index);
  finish_view_analysis(analysis, parameters);
}

}  // namespace

ViewAnalysis analyze_view(const RangeImage& image, const CosmosParameters& parameters) {
  ViewAnalysis analysis;
  analysis.frames = fit_local_surfaces(image, parameters.fit);
  analyze_fitted_view(image, parameters, analysis);
  return analysis;
}

PartialWindowKernels& ViewAnalysisWorkspace::partial_window_kernels(
    const SurfaceFitParameters& fit) {
  if (!kernels_ || kernels_->side() != LocalSurfaceFitter::window_side(fit) ||
      kernels_->bicubic() != fit.bicubic)
    kernels_ =
        std::make_unique<PartialWindowKernels>(LocalSurfaceFitter::partial_window_kernels_for(
            fit, PartialWindowKernels::kStreamEntriesLog2));
  return *kernels_;
}

ViewAnalysis analyze_view(const RangeImage& image, const CosmosParameters& parameters,
                          ViewAnalysisWorkspace& workspace) {
  ViewAnalysis analysis;
  analysis.frames = DarbouxFrameField(image.width(), image.height());
  fit_local_surfaces(image, parameters.fit, analysis.frames,
                     workspace.partial_window_kernels(parameters.fit));
  analyze_fitted_view(image, parameters, analysis);
  return analysis;
}

void finish_view_analysis(ViewAnalysis& analysis, const CosmosParameters& parameters) {
  finish_view_analysis(analysis,
                       find_shape_seeds(analysis.frames, analysis.field, parameters.segmentation),
                       parameters);
}

void finish_view_analysis(ViewAnalysis& analysis, const ShapeSeeds& seeds,
                          const CosmosParameters& parameters) {
  analysis.segmentation = segment_csmps_from_seeds(analysis.field, seeds, parameters.segmentation);
  analysis.view = build_cosmos_view(analysis.frames, analysis.field, analysis.segmentation);
  analysis.spectrum = compute_shape_spectrum(analysis.field, parameters.spectrum);
  analysis.moments = spectrum_moments(analysis.spectrum);
  analysis.valid_pixels = 0;
  for (SurfaceLabel label : analysis.field.label.values())
    analysis.valid_pixels += label != SurfaceLabel::kInvalid ? 1 : 0;
}

}  // namespace cosmos
