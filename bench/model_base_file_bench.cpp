// Loading the model base (core/io/model_base_file.hpp): a synthetic base of 20 parts x 320
// views (§4.5), sized like real model views (the 25-part catalog built with the defaults:
// ~12 patches and on average 1,820 control points per view at the model surface's stride 3,
// here uniform in 820..2,820), and the same with stride-2 sizes (~4,100 points per view).
// The budget: load <= 2 s, <= 512 MB. Counters: file_MB, load_peak_MB (growth of the
// peak resident set while reading) and resident_MB (what the loaded base keeps). Also the
// on-demand unpacking of one view's registration points (the recognizer does it for the few
// candidate views of §5.2).
// Run: build/bench/model_base_file_bench
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/io/model_base_file.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

constexpr int kParts = 20;
constexpr int kViewsPerPart = 320;

CosmosView synthetic_cosmos(std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  CosmosView view;
  const int patches = 8 + static_cast<int>(random() % 8);
  for (int p = 0; p < patches; ++p) {
    Csmp patch;
    patch.id = p;
    patch.area_mm2 = 100 * unit(random);
    patch.mean_normal = Eigen::Vector3d(unit(random), unit(random), 1).normalized();
    patch.shape_index = unit(random);
    patch.centroid_mm = {unit(random), unit(random), unit(random)};
    patch.pixels = 500;
    for (int n = 0; n < 5; ++n) patch.neighbors.push_back({(p + n + 1) % patches, 20 + n});
    view.patches.push_back(patch);
    view.gauss_map.push_back({patch.mean_normal, {{patch.shape_index, patch.area_mm2, 1.0, {p}}}});
  }
  view.visible_area_mm2 = 5000;
  return view;
}

// A square control-point grid, 60 % of its cells with a point.
RegistrationPoints synthetic_registration(std::mt19937& random, int points) {
  RegistrationPoints r;
  r.grid_width = r.grid_height = static_cast<int>(std::ceil(std::sqrt(points / 0.6)));
  r.cell_point.assign(static_cast<std::size_t>(r.grid_width * r.grid_height), -1);
  r.position_mm.resize(3, points);
  r.normal.resize(3, points);
  r.surface.resize(kSurfaceCoefficients, points);
  r.residual_rms_mm.resize(points);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < points; ++i) {
    r.cell_point[static_cast<std::size_t>(i)] = i;
    r.surface.col(i) = SurfaceVector::NullaryExpr([&] { return unit(random); });
    r.position_mm.col(i) << i % r.grid_width, i / r.grid_width, r.surface(kHeight, i);
    r.normal.col(i) = Eigen::Vector3d(0.1 * unit(random), 0.1 * unit(random), 1).normalized();
    r.residual_rms_mm(i) = 0.02;
  }
  return r;
}

fs::path synthetic_base_file(int mean_points) {
  const fs::path path =
      fs::temp_directory_path() / ("cosmos_bench_base_" + std::to_string(::getpid()) + "_" +
                                   std::to_string(mean_points) + ".cmb");
  std::mt19937 random(42);
  ModelBase base;
  base.parameters_text = "{}\n";
  for (int part = 0; part < kParts; ++part) {
    base.parts.push_back(
        {"part" + std::to_string(part), "part.off", 100, 120, false, {}, {}, {}, {}, {}});
    for (int v = 0; v < kViewsPerPart; ++v) {
      ModelBaseView view;
      view.part_index = part;
      view.view_index = v;
      view.cosmos = synthetic_cosmos(random);
      const int points = mean_points - 1000 + static_cast<int>(random() % 2001);
      view.registration_packed = pack_registration_points(synthetic_registration(random, points));
      base.views.push_back(std::move(view));
    }
    for (int c = 0; c < 12; ++c) {
      ViewCluster cluster{part, {}, {}};
      for (int v = c; v < kViewsPerPart; v += 12) cluster.views.push_back(part * kViewsPerPart + v);
      base.clusters.push_back(cluster);
    }
  }
  write_model_base(base, path);
  return path;
}

double status_mb(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(field, 0) == 0)
      return std::stod(line.substr(std::string(field).size())) / 1024.0;
  return 0;
}

// Resets the peak resident set (VmHWM) to the current one (Linux >= 4.0).
void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }

void BM_LoadModelBase(benchmark::State& state) {
  const fs::path path = synthetic_base_file(static_cast<int>(state.range(0)));
  malloc_trim(0);
  double peak_mb = 0, resident_mb = 0;
  for (auto _ : state) {
    state.PauseTiming();
    malloc_trim(0);
    const double before_mb = status_mb("VmRSS:");
    reset_peak_rss();
    state.ResumeTiming();
    const ModelBase base = read_model_base(path);
    state.PauseTiming();
    peak_mb = std::max(peak_mb, status_mb("VmHWM:") - before_mb);
    resident_mb = status_mb("VmRSS:") - before_mb;
    benchmark::DoNotOptimize(base.views.data());
    state.ResumeTiming();
  }
  state.counters["file_MB"] = static_cast<double>(fs::file_size(path)) / (1024.0 * 1024.0);
  state.counters["load_peak_MB"] = peak_mb;
  state.counters["resident_MB"] = resident_mb;
  fs::remove(path);
}
BENCHMARK(BM_LoadModelBase)->Arg(1820)->Arg(4100)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_UnpackOneView(benchmark::State& state) {
  std::mt19937 random(1);
  const PackedRegistrationPoints packed =
      pack_registration_points(synthetic_registration(random, 1820));
  for (auto _ : state) benchmark::DoNotOptimize(unpack_registration_points(packed).surface.data());
}
BENCHMARK(BM_UnpackOneView)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmos
