#pragma once
// The whole chapter-3 pipeline for one range image (Fig. 3.22): local surface fit ->
// curvature-consistency smoothing -> shape index / curvedness / planar label -> CSMPs ->
// COSMOS -> shape spectrum and moments.
#include <memory>

#include "core/cosmos_parameters.hpp"
#include "core/range_image.hpp"
#include "core/representation/cosmos_view.hpp"
#include "core/representation/shape_spectrum.hpp"
#include "core/segmentation/csmp_segmentation.hpp"
#include "core/surface/darboux_frame_field.hpp"
#include "core/surface/partial_window_kernels.hpp"
#include "core/surface/shape_index.hpp"

namespace cosmos {

struct ViewAnalysis {
  DarbouxFrameField frames;
  ShapeIndexField field;
  CsmpSegmentation segmentation;
  CosmosView view;
  ShapeSpectrum spectrum;
  MomentVector moments{};
  std::size_t valid_pixels = 0;
};

ViewAnalysis analyze_view(const RangeImage& image, const CosmosParameters& parameters);

// What the analysis of one image learns that the next one's reuses: the least-squares kernels
// of the fit windows that borders, holes and silhouettes leave partial
// (core/surface/partial_window_kernels.hpp), each a function of its validity pattern alone.
// A stream of images analysed with one workspace (a model base's views, a run of scans) solves
// each pattern once, and every analysis equals analyze_view's bit for bit. Not shared between
// threads: one per worker.
class ViewAnalysisWorkspace {
 public:
  // The table for `fit`'s window, made anew when the window differs from the last one's.
  PartialWindowKernels& partial_window_kernels(const SurfaceFitParameters& fit);

 private:
  std::unique_ptr<PartialWindowKernels> kernels_;
};

ViewAnalysis analyze_view(const RangeImage& image, const CosmosParameters& parameters,
                          ViewAnalysisWorkspace& workspace);

// The stages after the per-pixel fields (Fig. 3.22 from CSMPs on): CSMP segmentation, the
// COSMOS, the shape spectrum and its moments, and the valid-pixel count, from the analysis's
// frames and field. Whole-image analysis and the real-time part builder both end here, so a
// live part and a model view are finished by the same code.
void finish_view_analysis(ViewAnalysis& analysis, const CosmosParameters& parameters);
// The same from the CSMP seeds of the analysis's field, already found (the real-time part
// builder finds them row by row: realtime/loop/row_seeds.hpp).
void finish_view_analysis(ViewAnalysis& analysis, const ShapeSeeds& seeds,
                          const CosmosParameters& parameters);

}  // namespace cosmos
