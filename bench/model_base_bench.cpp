// A real model base on disk and in memory (core/io/model_base_file.hpp): the acceptance of
// the cell's users is <= 4 MB per part on disk, a load in <= 1 s per 100 parts, and a small
// resident set for the loaded base plus each part's distance field of the pose search
// (core/recognition/part_pose_search.hpp). The base is COSMOS_MODEL_BASE, else the regression
// base the tests build (5 parts x 80 views); e.g. a 320-view base of the same catalog:
//   build/apps/cosmos modelbase build --catalog config/parts-regression.yaml --views 320
//     --out /tmp/regression-320.cmb
//   COSMOS_MODEL_BASE=/tmp/regression-320.cmb build/bench/model_base_bench
// Counters: MB_per_part (file), load_s_per_100_parts (wall clock; load_cpu_s_per_100_parts
// the reading thread's CPU time, which other work on the machine does not inflate),
// resident_MB (the loaded base), field_resident_MB (the distance fields; field_MB their
// voxels' bytes), and the file's bytes per table in MB (each the payload's size less that of
// the payload without the table).
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/io/model_base_file.hpp"
#include "core/io/model_base_payload.hpp"
#include "core/recognition/part_pose_search.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

fs::path base_path() {
  const char* path = std::getenv("COSMOS_MODEL_BASE");
  return path ? fs::path(path) : fs::path(COSMOS_REGRESSION_MODEL_BASE);
}

double resident_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0;
}

double thread_cpu_s() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double payload_mb(const ModelBase& base) {
  flatbuffers::FlatBufferBuilder builder(estimated_payload_bytes(base));
  encode_model_base(base, builder);
  return builder.GetSize() / (1024.0 * 1024.0);
}

void BM_LoadRealModelBase(benchmark::State& state) {
  const fs::path path = base_path();
  if (!fs::exists(path)) {
    state.SkipWithError(("no model base at " + path.string()).c_str());
    return;
  }
  double base_mb = 0, field_mb = 0, load_s = 0, load_cpu_s = 0;
  std::size_t field_bytes = 0;
  std::size_t parts = 0;
  for (auto _ : state) {
    malloc_trim(0);
    const double before_mb = resident_mb();
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_s();
    const ModelBase base = read_model_base(path);
    load_cpu_s += thread_cpu_s() - cpu_start;
    load_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.PauseTiming();
    base_mb = resident_mb() - before_mb;
    parts = base.parts.size();
    std::vector<PartSearchModel> models;
    field_bytes = 0;
    for (int part = 0; part < static_cast<int>(parts); ++part) {
      models.push_back(build_part_search_model(base, part));
      field_bytes += models.back().field.memory_bytes();
    }
    malloc_trim(0);
    field_mb = resident_mb() - before_mb - base_mb;
    benchmark::DoNotOptimize(models.data());
    state.ResumeTiming();
  }
  const double file_mb = static_cast<double>(fs::file_size(path)) / (1024.0 * 1024.0);
  state.counters["MB_per_part"] = file_mb / static_cast<double>(std::max<std::size_t>(parts, 1));
  state.counters["load_s_per_100_parts"] = load_s / static_cast<double>(state.iterations()) *
                                           100.0 /
                                           static_cast<double>(std::max<std::size_t>(parts, 1));
  state.counters["load_cpu_s_per_100_parts"] = load_cpu_s /
                                               static_cast<double>(state.iterations()) * 100.0 /
                                               static_cast<double>(std::max<std::size_t>(parts, 1));
  state.counters["resident_MB"] = base_mb;
  state.counters["field_resident_MB"] = field_mb;
  state.counters["field_MB"] = static_cast<double>(field_bytes) / (1024.0 * 1024.0);
}
BENCHMARK(BM_LoadRealModelBase)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_TableBytes(benchmark::State& state) {
  const fs::path path = base_path();
  if (!fs::exists(path)) {
    state.SkipWithError(("no model base at " + path.string()).c_str());
    return;
  }
  const ModelBase base = read_model_base(path);
  double whole = 0, registration = 0, patches = 0, gauss_maps = 0, clusters = 0;
  for (auto _ : state) {
    whole = payload_mb(base);
    ModelBase without = base;
    for (ModelBaseView& view : without.views) {
      view.registration_packed = PackedRegistrationPoints{};
      view.registration = RegistrationPoints{};
    }
    registration = whole - payload_mb(without);
    without = base;
    for (ModelBaseView& view : without.views) view.cosmos.patches.clear();
    patches = whole - payload_mb(without);
    without = base;
    for (ModelBaseView& view : without.views) view.cosmos.gauss_map.clear();
    gauss_maps = whole - payload_mb(without);
    without = base;
    without.clusters.clear();
    clusters = whole - payload_mb(without);
  }
  state.counters["payload_MB"] = whole;
  state.counters["registration_MB"] = registration;
  state.counters["patches_MB"] = patches;
  state.counters["gauss_maps_MB"] = gauss_maps;
  state.counters["clusters_MB"] = clusters;
  std::size_t points = 0;
  for (const ModelBaseView& view : base.views)
    points += static_cast<std::size_t>(view.registration_packed.size());
  state.counters["registration_bytes_per_point"] =
      registration * 1024.0 * 1024.0 / static_cast<double>(std::max<std::size_t>(points, 1));
}
BENCHMARK(BM_TableBytes)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace cosmos
