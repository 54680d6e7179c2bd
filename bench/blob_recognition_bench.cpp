// The recognition time of a blob holding k parts (realtime/cell/blob_recognition.hpp): the
// simulated source's regression catalog in groups of k parts touching end to end
// (sim_source.group_size), 40 mm between groups, through the scan loop; each completed blob
// recognized by recognize_blob on this thread, timed from the builder in hand to its last
// part's pose:
//   BlobRecognition/parts_per_group:K
//                     touching parts often meet in no pixel and come out as separate blobs,
//                     so blobs are sorted by the parts they reported: ms_blob_of_N, the mean
//                     wall-clock time of a blob that reported N parts (1-3), and blobs_of_N,
//                     how many; the extra time for a blob of k parts is ms_blob_of_k - k x
//                     ms_blob_of_1
// Needs the catalog meshes (scripts/fetch_catalog.sh) and the regression model base:
// $COSMOS_BENCH_MODEL_BASE, else build/test-data/regression-80.cmb (ctest builds it).
// Run: build/bench/blob_recognition_bench
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/blob_recognition.hpp"
#include "realtime/loop/scan_loop.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_source.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

constexpr int kGroups = 8;

fs::path model_base_path() {
  const char* path = std::getenv("COSMOS_BENCH_MODEL_BASE");
  return path ? fs::path(path) : fs::path(COSMOS_REGRESSION_MODEL_BASE);
}

void BM_BlobRecognition(benchmark::State& state) {
  const int parts_per_group = static_cast<int>(state.range(0));
  const ModelBase base = read_model_base(model_base_path());
  const PartCatalog catalog =
      read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml");
  const Recognizer recognizer(base, CosmosParameters{}, RecognitionParameters{});
  SimulatedSourceSettings settings;
  settings.parts = kGroups * parts_per_group;
  settings.group_size = parts_per_group;
  settings.seed = 5;
  constexpr int kSizes = 4;
  double total_ms[kSizes] = {};
  int blobs[kSizes] = {};
  for (auto _ : state) {
    SimulatedSource source(catalog, ScannerParameters{}, settings);
    source.start();
    ScanLoop loop(ScanLoopSettings{});
    PartRecognitionContext context;
    context.recognizer = &recognizer;
    context.model_base = &base;
    context.catalog_index_of_base_part.assign(base.parts.size(), -1);
    context.x0_loop_mm = loop.x0_loop_mm();
    Profile profile;
    source.reserve(profile);
    const auto recognize_completed = [&] {
      int index = -1;
      while (loop.completed().try_pop(index)) {
        const auto start = std::chrono::steady_clock::now();
        const BlobRecognition blob = recognize_blob(loop.builder(index), context, 0);
        const int size = std::min(static_cast<int>(blob.parts.size()), kSizes - 1);
        total_ms[size] +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        ++blobs[size];
        loop.returned().try_push(index);
      }
      SpeculativePart ahead;  // recognized at completion here: declined
      while (loop.speculative().try_pop(ahead)) loop.speculated().try_push(ahead.builder);
    };
    while (source.next(profile) == SourceStatus::kOk) {
      loop.process(profile);
      recognize_completed();
    }
    loop.flush();
    recognize_completed();
  }
  for (int size = 1; size < kSizes; ++size) {
    const std::string n = std::to_string(size);
    state.counters["blobs_of_" + n] = blobs[size];
    state.counters["ms_blob_of_" + n] = blobs[size] ? total_ms[size] / blobs[size] : 0;
  }
}
BENCHMARK(BM_BlobRecognition)
    ->Name("BlobRecognition")
    ->ArgName("parts_per_group")
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cosmos
