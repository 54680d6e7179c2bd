// Camera frame → profile throughput of the firmware_bridge path, on one core: stripe
// extraction (both peak methods, 8- and 16-bit) on 1280 x 256 ROI frames, then
// triangulation + resampling of one frame's peaks. The project's target is ≥ 1,000 frames/s.
// items_per_second is frames per second.
#include <benchmark/benchmark.h>

#include <vector>

#include "core/profile.hpp"
#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "firmware_bridge/laser_triangulation.hpp"
#include "firmware_bridge/profile_resampling.hpp"
#include "scanner/triangulation_geometry.hpp"
#include "tests/firmware_bridge/synthetic_stripe.hpp"

namespace {

using namespace cosmos;

constexpr int kColumns = 1280;
constexpr int kRoiRows = 256;

// A noisy σ = 2 px stripe wandering over the middle of the ROI, as a part passes.
cv::Mat bench_frame(bool sixteen_bit) {
  const auto centres = test::wandering_centres(kColumns, 128.0, 60.0);
  return sixteen_bit ? test::render_stripe<std::uint16_t>(centres, kRoiRows, {2.0, 40000.0},
                                                          {300.0, 0.01, 0.5}, 1)
                     : test::render_stripe<std::uint8_t>(centres, kRoiRows, {2.0, 200.0},
                                                         {2.0, 0.01, 40.0}, 1);
}

StripeExtractionParameters bench_parameters(StripePeakMethod method, bool sixteen_bit) {
  StripeExtractionParameters p;
  p.method = method;
  p.threshold = sixteen_bit ? 20 * 257 : 20;
  p.min_peak_intensity = sixteen_bit ? 40 * 257 : 40;
  return p;
}

void BM_ExtractStripe(benchmark::State& state, StripePeakMethod method, bool sixteen_bit) {
  const cv::Mat frame = bench_frame(sixteen_bit);
  LaserStripeExtractor extractor(bench_parameters(method, sixteen_bit));
  StripePeaks peaks;
  extractor.reserve(kColumns, peaks);
  for (auto _ : state) {
    extractor.extract(frame, {320, 0}, peaks);
    benchmark::DoNotOptimize(peaks.row_px.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["valid_columns"] = peaks.valid_columns;
}
BENCHMARK_CAPTURE(BM_ExtractStripe, centre_of_gravity_8bit, StripePeakMethod::kCentreOfGravity,
                  false);
BENCHMARK_CAPTURE(BM_ExtractStripe, gaussian_3pt_8bit, StripePeakMethod::kGaussianThreePoint,
                  false);
BENCHMARK_CAPTURE(BM_ExtractStripe, centre_of_gravity_16bit, StripePeakMethod::kCentreOfGravity,
                  true);
BENCHMARK_CAPTURE(BM_ExtractStripe, gaussian_3pt_16bit, StripePeakMethod::kGaussianThreePoint,
                  true);

// One frame's peaks → points on the laser plane → a 1280-sample profile (0.2 mm grid).
void BM_TriangulateAndResample(benchmark::State& state) {
  const TriangulationGeometry geometry = make_triangulation_geometry();
  const LaserTriangulator triangulator(geometry);
  LaserStripeExtractor extractor(bench_parameters(StripePeakMethod::kCentreOfGravity, false));
  StripePeaks peaks;
  extractor.extract(bench_frame(false), {geometry.roi_row_offset_px, 0}, peaks);
  TriangulatedStripe stripe;
  triangulator.reserve(kColumns, stripe);
  Profile profile;
  profile.x0_mm = -128.0;
  profile.dx_mm = 0.2;
  profile.resize(kColumns);
  const ProfileResamplingParameters resampling;
  for (auto _ : state) {
    triangulator.triangulate(peaks, stripe);
    benchmark::DoNotOptimize(resample_to_profile(stripe.x_mm, stripe.z_mm, resampling, profile));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TriangulateAndResample);

// The whole per-frame hardware path: extraction (centre of gravity, 8-bit) + triangulation
// + resampling.
void BM_FrameToProfile(benchmark::State& state) {
  const TriangulationGeometry geometry = make_triangulation_geometry();
  const LaserTriangulator triangulator(geometry);
  const cv::Mat frame = bench_frame(false);
  LaserStripeExtractor extractor(bench_parameters(StripePeakMethod::kCentreOfGravity, false));
  StripePeaks peaks;
  extractor.reserve(kColumns, peaks);
  TriangulatedStripe stripe;
  triangulator.reserve(kColumns, stripe);
  Profile profile;
  profile.x0_mm = -128.0;
  profile.dx_mm = 0.2;
  profile.resize(kColumns);
  const ProfileResamplingParameters resampling;
  for (auto _ : state) {
    extractor.extract(frame, {geometry.roi_row_offset_px, 0}, peaks);
    triangulator.triangulate(peaks, stripe);
    benchmark::DoNotOptimize(resample_to_profile(stripe.x_mm, stripe.z_mm, resampling, profile));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FrameToProfile);

}  // namespace
