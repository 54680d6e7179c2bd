// Speed of the real-time cell on streams of the simulated source, regression catalog
// (config/parts-regression.yaml), profiles across the default 256 mm field of view:
//   ScanLoopProcess/points:W/smoothing:I
//                     the acquisition thread's per-profile work, ScanLoop::process alone
//                     (conditioning onto the 0.4 mm grid, tracking, incremental COSMOS) on
//                     W-point profiles with I smoothing iterations (15 = default, 0 = off);
//                     time per profile, p50_us and p999_us (wall clock) and cpu_p50_us and
//                     cpu_p999_us (thread CPU time) over every profile timed
//   Conditioning/W    ProfileConditioner::condition alone: raw input points per second
//   PartEndSegmentation
//                     the CSMP segmentation of a part's view at its end: searched in the view
//                     against grown from the seeds its builder found row by row
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
#include <array>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/io/model_base_file.hpp"
#include "core/modelbase/model_base.hpp"
#include "core/recognition/recognizer.hpp"
#include "core/segmentation/csmp_segmentation.hpp"
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

// Parts in the pre-generated streams: enough part rows, part ends and empty belt between them
// for a p99.9 over a few thousand profiles, few enough to generate 3200-point streams quickly.
constexpr int kStreamParts = 5;
constexpr int kCellParts = 12;   // unpaced whole-cell run: enough parts for a stable median
constexpr int kPacedParts = 32;  // paced run: real time, about 5 s of belt
constexpr std::uint64_t kSeed = 7;
// Profiles timed per ScanLoopProcess run: about five passes over the 5-part stream, so p99.9
// is the 10th slowest of 10,000 rather than an estimate from the iteration count the library
// would pick (a pass or so).
constexpr int kTimedProfiles = 10000;

// The regression catalog, or $COSMOS_BENCH_CATALOG (e.g. config/parts.yaml with the default
// cell's model base in $COSMOS_BENCH_MODEL_BASE).
const PartCatalog& bench_catalog() {
  static const PartCatalog catalog = [] {
    const char* from_environment = std::getenv("COSMOS_BENCH_CATALOG");
    return read_part_catalog(from_environment != nullptr && *from_environment != '\0'
                                 ? fs::path(from_environment)
                                 : fs::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml");
  }();
  return catalog;
}

SimulatedSourceSettings source_settings(int parts) {
  SimulatedSourceSettings settings;
  settings.parts = parts;
  settings.seed = kSeed;
  return settings;
}

// A whole simulated stream in memory, so that the timed loops run no ray casting.
struct SimStream {
  std::vector<Profile> profiles;
  std::string error;  // why there is no stream (e.g. catalog meshes missing)
};

const SimStream& sim_stream(int points_per_profile) {
  static std::map<int, SimStream> streams;
  const auto [entry, inserted] = streams.try_emplace(points_per_profile);
  SimStream& stream = entry->second;
  if (!inserted) return stream;
  try {
    ScannerParameters parameters;
    parameters.points_per_profile = points_per_profile;
    SimulatedSource source(bench_catalog(), parameters, source_settings(kStreamParts));
    if (source.start() != SourceStatus::kOk) {
      stream.error = std::string(source.last_error());
      return stream;
    }
    Profile profile;
    source.reserve(profile);
    while (source.next(profile) == SourceStatus::kOk) stream.profiles.push_back(profile);
    if (stream.profiles.empty()) stream.error = "the simulated source gave no profiles";
  } catch (const std::exception& e) {
    stream.error = std::string(e.what()) + " (catalog meshes: scripts/fetch_catalog.sh)";
  }
  return stream;
}

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

// The value `fraction` of the way up the sorted values (0.5: the median).
double quantile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0;
  const auto at =
      values.begin() + static_cast<std::ptrdiff_t>(std::min(
                           values.size() - 1, static_cast<std::size_t>(fraction * values.size())));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

double median(std::vector<double> values) { return quantile(std::move(values), 0.5); }

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

// The CSMP segmentation left at a part's end, on the views of the stream's parts (640-point
// profiles) cut out of their builders: searched in the view (segment_csmps, as before the
// builder found seeds) against grown from the seeds the builder found row by row
// (RowSeeds::view_seeds, then segment_csmps_from_seeds). Per part, the least time of the
// iterations; the counters are the median and the largest over the parts, for the seeds
// alone (seeds_search_ms, seeds_from_rows_ms) and the whole segmentation (search_ms,
// from_rows_ms); parts_from_rows counts the parts whose builder's seeds held.
void PartEndSegmentation(benchmark::State& state) {
  const SimStream& stream = sim_stream(640);
  if (!stream.error.empty()) {
    state.SkipWithError(stream.error.c_str());
    return;
  }
  ScanLoopSettings settings;
  settings.parts.speculative_recognition = false;
  ScanLoop loop(settings);
  PartRecognitionContext context;
  context.x0_loop_mm = loop.x0_loop_mm();
  struct Part {
    BuiltPart built;
    PartView view;
  };
  std::vector<Part> parts;
  const auto take_completed = [&] {
    int index = -1;
    while (loop.completed().try_pop(index)) {
      loop.builder(index).cosmos.finish();
      const BuiltPart built = loop.builder(index).built();
      parts.push_back({built, extract_part_view(built, context)});
    }
  };
  for (const Profile& profile : stream.profiles) {
    loop.process(profile);
    take_completed();
  }
  loop.flush();
  take_completed();
  const SegmentationParameters& parameters = context.cosmos.segmentation;
  constexpr double kUnset = 1e30;
  std::vector<std::array<double, 4>> least_ms(parts.size(), {kUnset, kUnset, kUnset, kUnset});
  const auto timed_ms = [](auto&& work) {
    const std::int64_t start_ns = monotonic_now_ns();
    work();
    return static_cast<double>(monotonic_now_ns() - start_ns) * 1e-6;
  };
  int from_rows = 0;
  for (auto _ : state) {
    from_rows = 0;
    for (std::size_t n = 0; n < parts.size(); ++n) {
      const Part& part = parts[n];
      const DarbouxFrameField& frames = part.view.analysis.frames;
      const ShapeIndexField& field = part.view.analysis.field;
      const RowSeeds& row_seeds = part.built.cosmos->seeds();
      const int first_column = part_view_first_column(part.built);
      std::array<double, 4> ms{};
      ms[0] =
          timed_ms([&] { benchmark::DoNotOptimize(find_shape_seeds(frames, field, parameters)); });
      ms[1] =
          timed_ms([&] { benchmark::DoNotOptimize(row_seeds.view_seeds(field, first_column)); });
      ms[2] = timed_ms([&] { benchmark::DoNotOptimize(segment_csmps(frames, field, parameters)); });
      ms[3] = timed_ms([&] {
        const std::optional<ShapeSeeds> seeds = row_seeds.view_seeds(field, first_column);
        if (seeds) benchmark::DoNotOptimize(segment_csmps_from_seeds(field, *seeds, parameters));
      });
      from_rows += part.view.seeds_from_rows ? 1 : 0;
      for (int k = 0; k < 4; ++k) least_ms[n][k] = std::min(least_ms[n][k], ms[k]);
    }
  }
  const std::string names[4] = {"seeds_search", "seeds_from_rows", "search", "from_rows"};
  for (int k = 0; k < 4; ++k) {
    std::vector<double> values;
    for (const auto& part : least_ms) values.push_back(part[k]);
    state.counters[names[k] + "_ms"] = median(values);
    state.counters[names[k] + "_max_ms"] =
        values.empty() ? 0 : *std::max_element(values.begin(), values.end());
  }
  state.counters["parts"] = static_cast<double>(parts.size());
  state.counters["parts_from_rows"] = from_rows;
}
BENCHMARK(PartEndSegmentation)->Iterations(20)->UseRealTime()->Unit(benchmark::kMillisecond);

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
