// Speed of the simulated laser-line scanner on a catalog part (bunny, 90 mm, resting pose):
//   ProfileMode/W     profiles per second of W points (profile mode, the geometry path), over
//                     the profiles of one scan of the part (2 mm margin each side)
//   ProfileModePart/NAME  the same at 640 points for every part of the default catalog
//   CameraMode        frames per second of 1280 × 256 ROI frames, drawing + stripe extraction +
//                     triangulation + resampling included
//   ModelViewScan     time per model view (scan of one view-sphere pose, profile mode)
// One thread throughout. Needs the catalog meshes (scripts/fetch_catalog.sh).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "scanner/conditioning_parameters.hpp"
#include "sim/conveyor_scene.hpp"
#include "sim/mesh.hpp"
#include "sim/model_views.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_pose.hpp"
#include "sim/simulated_scanner.hpp"

namespace cosmos {
namespace {

constexpr const char* kPart = "bunny";

// The default catalog, or nullopt when it or its mesh cache is missing.
const std::optional<PartCatalog>& bench_catalog() {
  static const std::optional<PartCatalog> catalog = []() -> std::optional<PartCatalog> {
    try {
      return read_part_catalog(find_part_catalog());
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }();
  return catalog;
}

std::optional<TriangleMesh> load_part_mesh(const std::string& name) {
  if (!bench_catalog()) return std::nullopt;
  try {
    const PartEntry& part = bench_catalog()->at(name);
    return load_mesh(part.mesh_path, part.size_mm);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The bench part's mesh, or nullopt when the catalog cache is missing.
const std::optional<TriangleMesh>& bench_mesh() {
  static const std::optional<TriangleMesh> mesh = load_part_mesh(kPart);
  return mesh;
}

std::unique_ptr<ConveyorScene> bench_scene(const TriangleMesh& mesh, const std::string& name) {
  auto scene = std::make_unique<ConveyorScene>();
  const int mesh_index = scene->add_mesh(mesh);
  scene->add_part(name, mesh_index, place_on_belt(mesh, resting_rotation(mesh, 1)));
  scene->commit();
  return scene;
}

void scan_profiles(benchmark::State& state, const ScannerParameters& parameters, ScanMode mode,
                   const char* counter, const std::optional<TriangleMesh>& mesh = bench_mesh(),
                   const std::string& name = kPart) {
  if (!mesh) {
    state.SkipWithError("catalog meshes missing: run scripts/fetch_catalog.sh");
    return;
  }
  const auto scene = bench_scene(*mesh, name);
  SimulatedScanner scanner(*scene, parameters, mode);
  Profile profile;
  scanner.reserve(profile);
  const ProfileRange range = profiles_covering(*scene, parameters, 2.0);
  // Samples above the belt (the work is where the part is), counted outside the timed loop.
  const double belt_threshold_mm = ConditioningParameters{}.height_threshold_mm;
  double part_samples = 0.0;
  for (std::int64_t k = range.first; k <= range.last; ++k) {
    scanner.acquire(k, profile);
    for (const float z : profile.z_mm) part_samples += z > belt_threshold_mm;
  }
  std::int64_t k = range.first;
  for (auto _ : state) {
    scanner.acquire(k, profile);
    benchmark::DoNotOptimize(profile.z_mm.data());
    k = k == range.last ? range.first : k + 1;
  }
  state.counters[counter] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["profiles_per_scan"] = static_cast<double>(range.count());
  state.counters["part_samples"] = part_samples / static_cast<double>(range.count());
}

void ProfileMode(benchmark::State& state) {
  ScannerParameters parameters;
  parameters.points_per_profile = static_cast<int>(state.range(0));
  scan_profiles(state, parameters, ScanMode::kProfile, "profiles_per_s");
}
BENCHMARK(ProfileMode)->Arg(640)->Arg(1280)->Unit(benchmark::kMicrosecond);

// One benchmark per default catalog part (none when the catalog is missing).
const bool kPartBenchmarksRegistered = [] {
  if (!bench_catalog()) return false;
  for (const PartEntry& part : bench_catalog()->parts) {
    benchmark::RegisterBenchmark(("ProfileModePart/" + part.name).c_str(),
                                 [name = part.name](benchmark::State& state) {
                                   const std::optional<TriangleMesh> mesh = load_part_mesh(name);
                                   scan_profiles(state, ScannerParameters{}, ScanMode::kProfile,
                                                 "profiles_per_s", mesh, name);
                                 })
        ->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

void CameraMode(benchmark::State& state) {
  ScannerParameters parameters;
  parameters.sensor_width_px = 1280;
  parameters.roi_height_px = 256;
  scan_profiles(state, parameters, ScanMode::kCamera, "frames_per_s");
}
BENCHMARK(CameraMode)->Unit(benchmark::kMicrosecond);

void ModelViewScan(benchmark::State& state) {
  if (!bench_mesh()) {
    state.SkipWithError("catalog meshes missing: run scripts/fetch_catalog.sh");
    return;
  }
  ModelViewRenderer renderer(*bench_mesh(), kPart, ScannerParameters{}, ConditioningParameters{});
  int index = 0;
  for (auto _ : state) {
    const ModelView view = renderer.scan_view(index);
    benchmark::DoNotOptimize(view.image.z_mm.data());
    index = (index + 37) % renderer.view_count();  // a spread of directions
  }
}
BENCHMARK(ModelViewScan)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cosmos
