// The chapter-3 pipeline, stage by stage, on a 640x480 range image of a free-form surface
// (the targets on one core: curvature + S_I <= 10 ms, 15 smoothing iterations <= 100 ms,
// segmentation <= 10 ms). Run: build/bench/cosmos_pipeline_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "core/representation/cosmos_pipeline.hpp"
#include "core/segmentation/shape_seeds.hpp"
#include "core/surface/curvature_consistency.hpp"
#include "core/surface/local_surface_fit.hpp"

namespace cosmos {
namespace {

// A smooth free-form relief: a few Gaussian bumps and dents on a gentle wave, 0.4 mm pixels,
// with sensor noise (the simulated cell's: 0.4 mm grid, 0.02 mm noise).
RangeImage free_form_surface(double noise_mm = 0.02) {
  RangeImage image(640, 480, 0.4, 0.4);
  std::mt19937_64 generator(5);
  std::normal_distribution<double> unit_noise(0.0, 1.0);
  struct Bump {
    double x, y, sigma, height;
  };
  const Bump bumps[] = {
      {60, 50, 18, 25}, {170, 120, 25, -15}, {200, 40, 12, 10}, {100, 150, 30, 20}};
  for (int row = 0; row < image.height(); ++row) {
    for (int column = 0; column < image.width(); ++column) {
      const double x = image.x_mm(column), y = image.y_mm(row);
      double z = 5 * std::sin(x / 23.0) * std::cos(y / 31.0);
      for (const Bump& b : bumps)
        z += b.height *
             std::exp(-((x - b.x) * (x - b.x) + (y - b.y) * (y - b.y)) / (2 * b.sigma * b.sigma));
      image.z_mm(column, row) = static_cast<float>(z + noise_mm * unit_noise(generator));
    }
  }
  return image;
}

const RangeImage& surface() {
  static const RangeImage image = free_form_surface();
  return image;
}

// Into fields allocated once, as the real-time loop works (its buffers come from config
// maxima); the next benchmark adds the allocation of fresh fields, as analyze_view does.
void BM_CurvatureAndShapeIndex(benchmark::State& state) {
  const CosmosParameters parameters;
  DarbouxFrameField frames(surface().width(), surface().height());
  ShapeIndexField field = make_shape_index_field(surface().width(), surface().height());
  for (auto _ : state) {
    fit_local_surfaces(surface(), parameters.fit, frames);
    classify_surface(frames, 0.4, 0.4, parameters.shape_index, field);
    benchmark::DoNotOptimize(field.shape_index.data());
  }
}
BENCHMARK(BM_CurvatureAndShapeIndex)->Unit(benchmark::kMillisecond);

void BM_CurvatureAndShapeIndexIntoNewFields(benchmark::State& state) {
  const CosmosParameters parameters;
  for (auto _ : state) {
    auto frames = fit_local_surfaces(surface(), parameters.fit);
    auto field = classify_surface(frames, 0.4, 0.4, parameters.shape_index);
    benchmark::DoNotOptimize(field.shape_index.data());
  }
}
BENCHMARK(BM_CurvatureAndShapeIndexIntoNewFields)->Unit(benchmark::kMillisecond);

void BM_Smoothing15Iterations(benchmark::State& state) {
  const CosmosParameters parameters;
  const auto fitted = fit_local_surfaces(surface(), parameters.fit);
  for (auto _ : state) {
    state.PauseTiming();
    auto frames = fitted;
    state.ResumeTiming();
    smooth_curvatures(frames, 0.4, 0.4, parameters.smoothing);
    benchmark::DoNotOptimize(frames.frame[kNx].data());
  }
}
BENCHMARK(BM_Smoothing15Iterations)->Unit(benchmark::kMillisecond);

struct Classified {
  DarbouxFrameField frames;
  ShapeIndexField field;
};

Classified classify(const RangeImage& image) {
  const CosmosParameters parameters;
  Classified c;
  c.frames = fit_local_surfaces(image, parameters.fit);
  smooth_curvatures(c.frames, 0.4, 0.4, parameters.smoothing);
  c.field = classify_surface(c.frames, 0.4, 0.4, parameters.shape_index);
  return c;
}

const Classified& classified() {
  static const Classified result = classify(surface());
  return result;
}

// Counters: the patches found, and what the growing queue starts from (shape_seeds.hpp):
// region_pixels, the seeds the raster pass leaves, the seed pairs it lists and how many of
// them are different.
void segment(benchmark::State& state, const Classified& c) {
  const CosmosParameters parameters;
  int patches = 0;
  for (auto _ : state) {
    const auto segmentation = segment_csmps(c.frames, c.field, parameters.segmentation);
    patches = segmentation.patch_count;
  }
  state.counters["patches"] = patches;
  const ShapeSeeds seeds = find_shape_seeds(c.frames, c.field, parameters.segmentation);
  std::vector<std::pair<std::int32_t, std::int32_t>> different = seeds.adjacent;
  std::sort(different.begin(), different.end());
  different.erase(std::unique(different.begin(), different.end()), different.end());
  state.counters["region_pixels"] = static_cast<double>(
      std::count_if(c.field.label.values().begin(), c.field.label.values().end(),
                    [](SurfaceLabel label) { return label != SurfaceLabel::kInvalid; }));
  state.counters["seeds"] = seeds.seed_count();
  state.counters["seed_pairs"] = static_cast<double>(seeds.adjacent.size());
  state.counters["different_seed_pairs"] = static_cast<double>(different.size());
}

void BM_Segmentation(benchmark::State& state) { segment(state, classified()); }
BENCHMARK(BM_Segmentation)->Unit(benchmark::kMillisecond);

// The same relief at lower sensor noise (state.range(0) in micrometres; 0 = none): what
// segmentation costs as the shape index gets smoother. Noise leaves many small seeds in the
// low-curvature regions, and the growing and folding work follows their number.
void BM_SegmentationAtNoise(benchmark::State& state) {
  static std::map<std::int64_t, Classified> views;
  const std::int64_t noise_um = state.range(0);
  if (!views.contains(noise_um))
    views.emplace(noise_um, classify(free_form_surface(noise_um * 1e-3)));
  segment(state, views.at(noise_um));
}
BENCHMARK(BM_SegmentationAtNoise)
    ->ArgName("noise_um")
    ->Arg(0)
    ->Arg(5)
    ->Arg(10)
    ->Arg(15)
    ->Unit(benchmark::kMillisecond);

void BM_CosmosAndSpectrum(benchmark::State& state) {
  const CosmosParameters parameters;
  const auto& c = classified();
  const auto segmentation = segment_csmps(c.frames, c.field, parameters.segmentation);
  for (auto _ : state) {
    const auto view = build_cosmos_view(c.frames, c.field, segmentation);
    const auto spectrum = compute_shape_spectrum(c.field, parameters.spectrum);
    benchmark::DoNotOptimize(spectrum_moments(spectrum));
    benchmark::DoNotOptimize(view.patches.data());
  }
}
BENCHMARK(BM_CosmosAndSpectrum)->Unit(benchmark::kMillisecond);

void BM_WholePipeline(benchmark::State& state) {
  const CosmosParameters parameters;
  for (auto _ : state) benchmark::DoNotOptimize(analyze_view(surface(), parameters).moments);
}
BENCHMARK(BM_WholePipeline)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cosmos
