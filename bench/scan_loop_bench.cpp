// Speed of the real-time cell on streams of the simulated source, regression catalog
// (config/parts-regression.yaml), profiles across the default 256 mm field of view:
//   ScanLoopProcess/points:W/smoothing:I
//                     the acquisition thread's per-profile work, ScanLoop::process alone
//                     (conditioning onto the 0.4 mm grid, tracking, incremental COSMOS) on
//                     W-point profiles with I smoothing iterations (15 = default, 0 = off);
//                     time per profile, p50_us and p999_us (wall clock) and cpu_p50_us and
//                     cpu_p999_us (thread CPU time) over every profile timed
//   Conditioning/W    ProfileConditioner::condition alone: raw input points per second
//   EndOfPartToPose   run_cell unpaced: the tracker completes a part -> its pose published,
//                     latency_p50_ms over the parts
//   PacedJitter       run_cell paced at the default line rate (2500 Hz): start-time jitter of
//                     the acquisition loop, start_jitter_{p50,p99,max}_us, and the end of
//                     part -> pose latency at the belt's pace, latency_p50_ms
//   PacedReplayLatency
//                     the same stream recorded to an LCM log once and replayed paced through
//                     ReplaySource, as a cell behind a real scanner runs: no ray casting on the
//                     acquisition thread, so the end of part -> pose latency_p50_ms and
//                     latency_p99_ms are the loop's and the recognizer's alone; blobs_ahead
//                     and blobs_at_completion: how many were recognized before the tracker
//                     completed them (speculative recognition) and how many at completion;
//                     groups: pieces a part's shadow cut apart, recognized as one
// Needs the catalog meshes (scripts/fetch_catalog.sh). The whole-cell runs also need the
// regression model base: $COSMOS_BENCH_MODEL_BASE, else build/test-data/regression-80.cmb
// (ctest builds it, tests/CMakeLists.txt). $COSMOS_BENCH_CATALOG replaces the regression
// catalog (its parts must be in the base); $COSMOS_BENCH_RECOGNITION_HELPERS replaces the
// cell's default realtime.recognition_helpers. Run: build/bench/scan_loop_bench
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/sim_stream.hpp"
#include "core/io/model_base_file.hpp"
#include "core/modelbase/model_base.hpp"
#include "core/recognition/recognizer.hpp"
#include "firmware_bridge/kernel_timestamp.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/cell/part_recognition.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "realtime/lcm/profile_log_writer.hpp"
#include "realtime/loop/profile_conditioner.hpp"
#include "realtime/loop/scan_loop.hpp"
#include "realtime/rt/helper_threads.hpp"
#include "realtime/rt/latency_histogram.hpp"
#include "realtime/sources/replay_source.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_source.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;
using bench::bench_catalog;
using bench::kSeed;
using bench::kStreamParts;
using bench::median;
using bench::quantile;
using bench::sim_stream;
using bench::SimStream;
using bench::source_settings;

constexpr int kCellParts = 12;   // unpaced whole-cell run: enough parts for a stable median
constexpr int kPacedParts = 32;  // paced run: real time, about 5 s of belt
// Profiles timed per ScanLoopProcess run: about five passes over the 5-part stream, so p99.9
// is the 10th slowest of 10,000 rather than an estimate from the iteration count the library
// would pick (a pass or so).
constexpr int kTimedProfiles = 10000;

// The calling thread's CPU time. Beside the wall clock it tells the loop's own tail from
// preemption: on a shared, loaded machine the wall-clock tail is mostly a scheduler slice
// (milliseconds) spent in another process.
std::int64_t thread_cpu_now_ns() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return timespec_to_ns(now);
}

// Builders go back as soon as the tracker completes a part: nothing recognizes them here, and
// the loop must never drop a part for want of one.
void return_builders(ScanLoop& loop) {
  int index = -1;
  while (loop.completed().try_pop(index)) loop.returned().try_push(index);
  SpeculativePart ahead;
  while (loop.speculative().try_pop(ahead)) loop.speculated().try_push(ahead.builder);
}

void ScanLoopProcess(benchmark::State& state) {
  const SimStream& stream = sim_stream(static_cast<int>(state.range(0)));
  if (!stream.error.empty()) {
    state.SkipWithError(stream.error.c_str());
    return;
  }
  ScanLoopSettings settings;
  settings.cosmos.smoothing.iterations = static_cast<int>(state.range(1));
  ScanLoop loop(settings);
  // One untimed pass first: the builders' buffers are touched (page faults) and every ring
  // has turned once, as in a cell that has been running for a while.
  for (const Profile& profile : stream.profiles) {
    loop.process(profile);
    return_builders(loop);
  }
  // Manual time: only process() counts, not the clock reads and the builders' return. The
  // stream repeats seamlessly, since it begins and ends with empty belt.
  LatencyHistogram profile_times, profile_cpu_times;
  std::size_t next = 0;
  for (auto _ : state) {
    const Profile& profile = stream.profiles[next];
    const std::int64_t start_cpu_ns = thread_cpu_now_ns();
    const std::int64_t start_ns = monotonic_now_ns();
    loop.process(profile);
    const std::int64_t time_ns = monotonic_now_ns() - start_ns;
    profile_cpu_times.record_ns(thread_cpu_now_ns() - start_cpu_ns);
    profile_times.record_ns(time_ns);
    state.SetIterationTime(static_cast<double>(time_ns) * 1e-9);
    return_builders(loop);
    next = next + 1 == stream.profiles.size() ? 0 : next + 1;
  }
  state.counters["p50_us"] = static_cast<double>(profile_times.p50_ns()) / 1e3;
  state.counters["p999_us"] = static_cast<double>(profile_times.p999_ns()) / 1e3;
  state.counters["max_us"] = static_cast<double>(profile_times.max_ns()) / 1e3;
  state.counters["cpu_p50_us"] = static_cast<double>(profile_cpu_times.p50_ns()) / 1e3;
  state.counters["cpu_p999_us"] = static_cast<double>(profile_cpu_times.p999_ns()) / 1e3;
  state.counters["stream_profiles"] = static_cast<double>(stream.profiles.size());
  state.counters["parts_dropped"] = static_cast<double>(loop.counters().parts_dropped.load());
}
BENCHMARK(ScanLoopProcess)
    ->ArgsProduct({{640, 1280, 3200}, {15, 0}})
    ->ArgNames({"points", "smoothing"})
    ->Iterations(kTimedProfiles)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);

void Conditioning(benchmark::State& state) {
  const SimStream& stream = sim_stream(static_cast<int>(state.range(0)));
  if (!stream.error.empty()) {
    state.SkipWithError(stream.error.c_str());
    return;
  }
  const ProfileConditioner conditioner{ConditioningParameters{}, SurfaceFitParameters{}};
  std::vector<float> row_z_mm(static_cast<std::size_t>(conditioner.width()));
  std::int64_t input_points = 0;
  std::size_t next = 0;
  for (auto _ : state) {
    const Profile& profile = stream.profiles[next];
    conditioner.condition(profile, row_z_mm.data());
    benchmark::DoNotOptimize(row_z_mm.data());
    benchmark::ClobberMemory();
    input_points += static_cast<std::int64_t>(profile.width());
    next = next + 1 == stream.profiles.size() ? 0 : next + 1;
  }
  state.SetItemsProcessed(input_points);
}
BENCHMARK(Conditioning)->Arg(640)->Arg(1280)->Arg(3200)->Unit(benchmark::kMicrosecond);

// The regression model base and its recognizer, loaded once for both whole-cell runs.
struct BenchRecognition {
  std::unique_ptr<ModelBase> base;
  std::unique_ptr<HelperThreads> helpers;
  std::unique_ptr<Recognizer> recognizer;
  std::string error;  // one line: why there is no model base
};

const BenchRecognition& bench_recognition() {
  static const BenchRecognition recognition = [] {
    BenchRecognition loaded;
    const char* from_environment = std::getenv("COSMOS_BENCH_MODEL_BASE");
    const fs::path path = from_environment != nullptr && *from_environment != '\0'
                              ? fs::path(from_environment)
                              : fs::path(COSMOS_REGRESSION_MODEL_BASE);
    try {
      loaded.base = std::make_unique<ModelBase>(read_model_base(path));
      // The base was built with the default parameters (tests/CMakeLists.txt).
      const char* helpers = std::getenv("COSMOS_BENCH_RECOGNITION_HELPERS");
      loaded.helpers = std::make_unique<HelperThreads>(
          helpers != nullptr && *helpers != '\0' ? std::atoi(helpers)
                                                 : CellThreadSettings{}.recognition_helpers);
      loaded.recognizer = std::make_unique<Recognizer>(
          *loaded.base, CosmosParameters{}, RecognitionParameters{}, loaded.helpers.get());
    } catch (const std::exception& e) {
      loaded.error = "cannot read the model base " + path.string() + " (" + e.what() +
                     "): set COSMOS_BENCH_MODEL_BASE or build it with ctest";
    }
    return loaded;
  }();
  return recognition;
}

PartRecognitionContext recognition_context(const BenchRecognition& recognition,
                                           const ScanLoop& loop) {
  PartRecognitionContext context;
  context.recognizer = recognition.recognizer.get();
  context.model_base = recognition.base.get();
  for (const ModelPart& part : recognition.base->parts) {
    const PartEntry* entry = bench_catalog().find(part.name);
    context.catalog_index_of_base_part.push_back(
        entry != nullptr ? static_cast<int>(entry - bench_catalog().parts.data()) : -1);
  }
  context.mm_per_tick = ScannerParameters{}.encoder_mm_per_tick;
  context.x0_loop_mm = loop.x0_loop_mm();
  return context;
}

// One whole-cell run of `parts` simulated parts of the regression catalog through a memory
// publisher, latency_ms measured (not zeroed); paced at the default line rate or unpaced with
// every part recognized. Appends each published pose's latency_ms; false after reporting an
// error on `state`.
bool run_bench_cell(benchmark::State& state, const BenchRecognition& recognition, int parts,
                    bool paced, CellRunSummary& summary, std::vector<double>& latencies_ms,
                    const PoseObserver& on_part = {}) {
  try {
    SimulatedSource source(bench_catalog(), ScannerParameters{}, source_settings(parts));
    if (source.start() != SourceStatus::kOk) {
      state.SkipWithError(std::string(source.last_error()).c_str());
      return false;
    }
    ScanLoopSettings loop_settings;
    loop_settings.wait_for_recognizer = !paced;  // unpaced: every part is recognized
    ScanLoop loop(loop_settings);
    MemoryPublisher publisher;
    CellRunSettings settings;
    settings.paced = paced;
    settings.line_rate_hz = ScannerParameters{}.line_rate_hz;
    settings.deterministic_output = false;
    summary = run_cell(source, loop, recognition_context(recognition, loop), publisher, settings,
                       on_part);
    for (const PartPose& pose : publisher.poses) latencies_ms.push_back(pose.latency_ms);
    return true;
  } catch (const std::exception& e) {
    state.SkipWithError(
        (std::string(e.what()) + " (catalog meshes: scripts/fetch_catalog.sh)").c_str());
    return false;
  }
}

// latency_ms runs from the tracker completing the part (the row after its last one) to the
// publisher sending its pose. Unpaced, this includes the part's recognition and, since the
// acquisition thread then outruns the belt and completes parts faster than they are
// recognized, the wait behind the parts completed before it. The first part waits behind none
// (latency_min_ms); the recognizer's own time per part is reported beside (recognize_p50_ms).
void EndOfPartToPose(benchmark::State& state) {
  const BenchRecognition& recognition = bench_recognition();
  if (!recognition.error.empty()) {
    state.SkipWithError(recognition.error.c_str());
    return;
  }
  std::vector<double> latencies_ms, recognize_ms;
  std::int64_t parts_seen = 0;
  for (auto _ : state) {
    CellRunSummary summary;
    if (!run_bench_cell(state, recognition, kCellParts, false, summary, latencies_ms,
                        [&recognize_ms](const PartRecognition& part) {
                          recognize_ms.push_back(part.result.timings.total_ms);
                        }))
      return;
    parts_seen += summary.parts_seen;
  }
  state.counters["latency_p50_ms"] = median(latencies_ms);
  state.counters["latency_min_ms"] =
      latencies_ms.empty() ? 0 : *std::min_element(latencies_ms.begin(), latencies_ms.end());
  state.counters["latency_max_ms"] =
      latencies_ms.empty() ? 0 : *std::max_element(latencies_ms.begin(), latencies_ms.end());
  state.counters["recognize_p50_ms"] = median(recognize_ms);
  state.counters["parts_seen"] = static_cast<double>(parts_seen);
  state.counters["poses"] = static_cast<double>(latencies_ms.size());
}
BENCHMARK(EndOfPartToPose)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);

// The jitter is the lateness of each period's start against its absolute deadline
// (deadline_pacer.hpp), with the recognizer and publisher threads running beside the loop.
void PacedJitter(benchmark::State& state) {
  const BenchRecognition& recognition = bench_recognition();
  if (!recognition.error.empty()) {
    state.SkipWithError(recognition.error.c_str());
    return;
  }
  CellRunSummary summary;
  std::vector<double> latencies_ms;
  for (auto _ : state)
    if (!run_bench_cell(state, recognition, kPacedParts, true, summary, latencies_ms)) return;
  state.counters["start_jitter_p50_us"] = summary.start_jitter_p50_us;
  state.counters["start_jitter_p99_us"] = summary.start_jitter_p99_us;
  state.counters["start_jitter_max_us"] = summary.start_jitter_max_us;
  // The period's work includes the simulated source's ray casting: a paced simulated cell
  // overruns where the same loop behind a real scanner might not.
  state.counters["overruns"] = static_cast<double>(summary.deadline_overruns);
  state.counters["profile_time_p50_us"] = summary.profile_time_p50_us;
  state.counters["profile_time_p999_us"] = summary.profile_time_p999_us;
  state.counters["profiles"] = static_cast<double>(summary.profiles);
  state.counters["parts_dropped"] = static_cast<double>(summary.parts_dropped);
  // End of part -> pose published at the belt's pace: recognition plus any wait behind the
  // previous part.
  state.counters["latency_p50_ms"] = median(latencies_ms);
  state.counters["poses"] = static_cast<double>(latencies_ms.size());
}
BENCHMARK(PacedJitter)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);

// The cell behind a scanner, without the simulator's ray casting competing for the two cores:
// the simulated stream is recorded once (set-up, untimed) and replayed paced.
void PacedReplayLatency(benchmark::State& state) {
  const BenchRecognition& recognition = bench_recognition();
  if (!recognition.error.empty()) {
    state.SkipWithError(recognition.error.c_str());
    return;
  }
  const fs::path log_path =
      fs::temp_directory_path() / ("cosmos-bench-replay-" + std::to_string(::getpid()) + ".lcmlog");
  try {
    SimulatedSource source(bench_catalog(), ScannerParameters{}, source_settings(kPacedParts));
    if (source.start() != SourceStatus::kOk) {
      state.SkipWithError(std::string(source.last_error()).c_str());
      return;
    }
    std::vector<Profile> profiles;
    Profile profile;
    source.reserve(profile);
    while (source.next(profile) == SourceStatus::kOk) profiles.push_back(profile);
    write_profile_log(log_path, profiles);
  } catch (const std::exception& e) {
    state.SkipWithError(
        (std::string(e.what()) + " (catalog meshes: scripts/fetch_catalog.sh)").c_str());
    return;
  }
  CellRunSummary summary;
  std::vector<double> latencies_ms, recognize_ms;
  int searched = 0;
  std::int64_t ahead = 0, at_completion = 0, held_for_successor = 0, groups = 0;
  for (auto _ : state) {
    ReplaySource source(log_path);
    if (source.start() != SourceStatus::kOk) {
      state.SkipWithError(std::string(source.last_error()).c_str());
      break;
    }
    ScanLoop loop{ScanLoopSettings{}};
    MemoryPublisher publisher;
    CellRunSettings settings;
    settings.paced = true;
    settings.line_rate_hz = ScannerParameters{}.line_rate_hz;
    summary = run_cell(source, loop, recognition_context(recognition, loop), publisher, settings,
                       [&](const PartRecognition& part) {
                         recognize_ms.push_back(part.result.timings.total_ms);
                         searched += std::any_of(
                             part.result.candidates.begin(), part.result.candidates.end(),
                             [](const RecognitionCandidate& c) { return c.from_pose_search; });
                       });
    for (const PartPose& pose : publisher.poses) latencies_ms.push_back(pose.latency_ms);
    ahead += summary.blobs_recognized_ahead;
    at_completion += summary.blobs_recognized_at_completion;
    held_for_successor += summary.blobs_held_for_successor;
    groups += summary.blob_groups_recognized;
  }
  fs::remove(log_path);
  state.counters["recognize_p50_ms"] = median(recognize_ms);
  state.counters["pose_searched"] = searched;
  state.counters["latency_p50_ms"] = median(latencies_ms);
  state.counters["latency_p99_ms"] = quantile(latencies_ms, 0.99);
  state.counters["blobs_ahead"] = static_cast<double>(ahead);
  state.counters["blobs_at_completion"] = static_cast<double>(at_completion);
  state.counters["held_for_successor"] = static_cast<double>(held_for_successor);
  state.counters["groups"] = static_cast<double>(groups);
  state.counters["latency_max_ms"] =
      latencies_ms.empty() ? 0 : *std::max_element(latencies_ms.begin(), latencies_ms.end());
  state.counters["poses"] = static_cast<double>(latencies_ms.size());
  state.counters["parts_dropped"] = static_cast<double>(summary.parts_dropped);
  state.counters["overruns"] = static_cast<double>(summary.deadline_overruns);
  state.counters["start_jitter_p99_us"] = summary.start_jitter_p99_us;
}
// Ten passes of the 32 parts: a p99 over a few hundred poses is the few slowest, where over
// one pass or three it would be the single slowest, one scheduling hiccup of the machine.
BENCHMARK(PacedReplayLatency)->Iterations(10)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cosmos
