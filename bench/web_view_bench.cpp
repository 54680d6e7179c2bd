// The acquisition loop's per-profile processing time with the live web view off, on with no
// browser, and on with a browser-like client connected, on the same paced stream:
//   AcquisitionWithWebView/fifo:P
//                     run_cell paced at the default line rate (2500 Hz) over a pre-generated
//                     simulated stream (no ray casting on the acquisition thread), the three
//                     setups taken in turn, kRounds rounds, so a change of machine load hits
//                     them alike. Per setup, the median over the rounds of each run's
//                     per-profile p50 and p99.9 (profile_time_*_us: the profile in hand to its
//                     last stage) and of its deadline overruns:
//                       *_off     no web view (the cell as without --http)
//                       *_idle    web view serving, nobody connected
//                       *_client  web view with a client reading /events (every summary and
//                                 part with its belt tile, as the page does) and polling
//                                 /api/status and /api/poses five times a second
//                     The client's bytes received are reported (client_kib) so a run whose
//                     client saw nothing is visible. fifo:0 runs the acquisition thread as
//                     the default config does (SCHED_OTHER); fifo:80 at SCHED_FIFO 80, as a
//                     cell configured for real time (realtime.sched_fifo_priority), where
//                     the view's threads can no longer preempt it (without the privilege
//                     the report says so: fifo_applied 0).
// The web view reads only what the publisher thread hands it, so the acquisition thread's
// times should not depend on it beyond what sharing the two cores costs.
// Needs the catalog meshes (scripts/fetch_catalog.sh) and the regression model base:
// $COSMOS_BENCH_MODEL_BASE, else build/test-data/regression-80.cmb (ctest builds it).
// Run: build/bench/web_view_bench
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/io/model_base_file.hpp"
#include "core/modelbase/model_base.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/cell/part_recognition.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "realtime/loop/scan_loop.hpp"
#include "realtime/web/web_view.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_source.hpp"

// Last: it pulls in <resolv.h>, whose `_res` macro breaks Eigen's headers included after it.
#include <httplib.h>

namespace cosmos {
namespace {

namespace fs = std::filesystem;

constexpr int kParts = 12;  // about 2 s of belt per run
constexpr int kRounds = 3;

enum class Setup { kOff, kIdle, kClient };
constexpr std::array<Setup, 3> kSetups = {Setup::kOff, Setup::kIdle, Setup::kClient};
const char* name_of(Setup setup) {
  return setup == Setup::kOff ? "off" : setup == Setup::kIdle ? "idle" : "client";
}

// A pre-generated stream replayed as a scanner would give it.
class MemorySource final : public ScannerSource {
 public:
  explicit MemorySource(const std::vector<Profile>& profiles) : profiles_(profiles) {}
  SourceStatus start() override {
    next_ = 0;
    return SourceStatus::kOk;
  }
  void reserve(Profile& profile) const override {
    profile.z_mm.reserve(profiles_.empty() ? 0 : profiles_.front().z_mm.size());
  }
  SourceStatus next(Profile& out) noexcept override {
    if (next_ == profiles_.size()) return SourceStatus::kEndOfStream;
    const Profile& from = profiles_[next_++];
    out.seq = from.seq;
    out.encoder_ticks = from.encoder_ticks;
    out.t_us = from.t_us;
    out.x0_mm = from.x0_mm;
    out.dx_mm = from.dx_mm;
    out.z_mm.assign(from.z_mm.begin(), from.z_mm.end());  // reserved: no allocation
    return SourceStatus::kOk;
  }
  void stop() noexcept override {}
  double mm_per_profile() const override { return ScannerParameters{}.profile_step_mm(); }
  std::string_view last_error() const noexcept override { return {}; }
  SourceHealth health() const noexcept override { return {}; }

 private:
  const std::vector<Profile>& profiles_;
  std::size_t next_ = 0;
};

struct BenchCell {
  PartCatalog catalog;
  std::unique_ptr<ModelBase> base;
  std::unique_ptr<Recognizer> recognizer;
  std::vector<Profile> stream;
  std::string error;
};

const BenchCell& bench_cell() {
  static const BenchCell cell = [] {
    BenchCell loaded;
    const char* from_environment = std::getenv("COSMOS_BENCH_MODEL_BASE");
    const fs::path base_path = from_environment != nullptr && *from_environment != '\0'
                                   ? fs::path(from_environment)
                                   : fs::path(COSMOS_REGRESSION_MODEL_BASE);
    try {
      loaded.catalog =
          read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml");
      loaded.base = std::make_unique<ModelBase>(read_model_base(base_path));
      loaded.recognizer =
          std::make_unique<Recognizer>(*loaded.base, CosmosParameters{}, RecognitionParameters{});
      SimulatedSourceSettings settings;
      settings.parts = kParts;
      SimulatedSource source(loaded.catalog, ScannerParameters{}, settings);
      if (source.start() != SourceStatus::kOk) {
        loaded.error = std::string(source.last_error());
        return loaded;
      }
      Profile profile;
      source.reserve(profile);
      while (source.next(profile) == SourceStatus::kOk) loaded.stream.push_back(profile);
    } catch (const std::exception& e) {
      loaded.error = std::string(e.what()) +
                     " (the regression model base: ctest or $COSMOS_BENCH_MODEL_BASE; the "
                     "catalog meshes: scripts/fetch_catalog.sh)";
    }
    return loaded;
  }();
  return cell;
}

// A browser's load: the event stream read to its end, the JSON API polled.
class BrowserLikeClient {
 public:
  explicit BrowserLikeClient(int port)
      : stream_([this, port] {
          httplib::Client http("127.0.0.1", port);
          http.set_read_timeout(60, 0);
          http.Get("/events", [this](const char*, std::size_t length) {
            bytes_ += static_cast<std::int64_t>(length);
            return true;
          });
        }),
        poller_([this, port] {
          httplib::Client http("127.0.0.1", port);
          while (!stopping_) {
            for (const char* path : {"/api/status", "/api/poses"})
              if (const auto reply = http.Get(path))
                bytes_ += static_cast<std::int64_t>(reply->body.size());
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
          }
        }) {}
  // After the web view stopped (which ends the stream).
  std::int64_t finish() {
    stopping_ = true;
    stream_.join();
    poller_.join();
    return bytes_;
  }

 private:
  std::atomic<std::int64_t> bytes_{0};
  std::atomic<bool> stopping_{false};
  std::thread stream_;
  std::thread poller_;
};

struct RunResult {
  CellRunSummary summary;
  std::int64_t client_bytes = 0;
};

RunResult run_once(const BenchCell& cell, Setup setup, int fifo_priority) {
  MemorySource source(cell.stream);
  source.start();
  ScanLoop loop(ScanLoopSettings{});
  PartRecognitionContext context;
  context.recognizer = cell.recognizer.get();
  context.model_base = cell.base.get();
  context.catalog_index_of_base_part.assign(cell.base->parts.size(), -1);
  context.mm_per_tick = ScannerParameters{}.encoder_mm_per_tick;
  context.x0_loop_mm = loop.x0_loop_mm();
  context.keep_part_image = setup != Setup::kOff;
  CellRunSettings settings;
  settings.line_rate_hz = ScannerParameters{}.line_rate_hz;
  settings.publishing.status_period_s = 0.25;  // a few summaries per run
  settings.threads.thread.sched_fifo_priority = fifo_priority;
  MemoryPublisher memory;

  // The acquisition thread is a fresh thread per run, so its real-time settings end with it
  // and never reach the web view's threads, which the bench's main thread starts.
  RunResult result;
  const auto run_on_own_thread = [&](Publisher& publisher, const PoseObserver& observer) {
    std::thread acquisition(
        [&] { result.summary = run_cell(source, loop, context, publisher, settings, observer); });
    acquisition.join();
  };
  if (setup == Setup::kOff) {
    run_on_own_thread(memory, {});
    return result;
  }
  WebView web(WebViewSettings{}, {"127.0.0.1", 0});
  web.set_belt(ConditioningParameters{}.grid_mm, loop.width(), loop.x0_loop_mm());
  std::unique_ptr<BrowserLikeClient> client;
  if (setup == Setup::kClient) client = std::make_unique<BrowserLikeClient>(web.port());
  run_on_own_thread(web.publisher(memory),
                    [&web](const PartRecognition& part) { web.observe(part); });
  web.stop();
  if (client) result.client_bytes = client->finish();
  return result;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

void AcquisitionWithWebView(benchmark::State& state) {
  const BenchCell& cell = bench_cell();
  if (!cell.error.empty()) {
    state.SkipWithError(cell.error.c_str());
    return;
  }
  struct Samples {
    std::vector<double> p50_us, p999_us, overruns;
  };
  std::array<Samples, kSetups.size()> samples;
  std::int64_t client_bytes = 0;
  bool fifo_applied = true;
  const int fifo_priority = static_cast<int>(state.range(0));
  for (auto _ : state) {
    for (int round = 0; round < kRounds; ++round) {
      for (std::size_t s = 0; s < kSetups.size(); ++s) {
        const RunResult run = run_once(cell, kSetups[s], fifo_priority);
        fifo_applied = fifo_applied && run.summary.realtime_report.starts_with("SCHED_FIFO");
        samples[s].p50_us.push_back(run.summary.profile_time_p50_us);
        samples[s].p999_us.push_back(run.summary.profile_time_p999_us);
        samples[s].overruns.push_back(static_cast<double>(run.summary.deadline_overruns));
        client_bytes += run.client_bytes;
      }
    }
  }
  for (std::size_t s = 0; s < kSetups.size(); ++s) {
    const std::string suffix = std::string("_") + name_of(kSetups[s]);
    state.counters["p50_us" + suffix] = median(samples[s].p50_us);
    state.counters["p999_us" + suffix] = median(samples[s].p999_us);
    state.counters["overruns" + suffix] = median(samples[s].overruns);
  }
  state.counters["client_kib"] = static_cast<double>(client_bytes) / 1024.0 / kRounds;
  state.counters["profiles"] = static_cast<double>(cell.stream.size());
  if (fifo_priority > 0) state.counters["fifo_applied"] = fifo_applied ? 1 : 0;
}
BENCHMARK(AcquisitionWithWebView)
    ->ArgName("fifo")
    ->Arg(0)
    ->Arg(80)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace
}  // namespace cosmos
