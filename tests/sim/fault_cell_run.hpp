#pragma once
// The cell run over one faulty source that the fault-injection tests share: catalog parts of
// config/parts-regression.yaml on the simulated belt, the regression model base, the stream
// checker every cell source passes through, unpaced (every part recognized), and a status
// every millisecond. So that the FAULT a fault raises is seen whatever the machine's load,
// the stream slows down once a fault total has grown (1 ms before each profile, which changes
// no data) until the publisher has sent a FAULT status. What comes back: the summary, every
// pose with its ground truth, and every status sent.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "realtime/sources/stream_checked_source.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/fault_plan.hpp"
#include "sim/source/simulated_conveyor.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos::testing {

inline SimulatedConveyorSettings fault_test_conveyor_settings() {
  SimulatedConveyorSettings settings;
  settings.parts = 4;
  settings.seed = 7;
  return settings;
}

inline const PartCatalog& fault_test_catalog() {
  static const PartCatalog catalog =
      read_part_catalog(std::filesystem::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml");
  return catalog;
}

// `fault` once in a stream of profiles 0 … last_profile: every_profiles half the stream, so
// the only run with an occurrence is the second half, and the first seed that starts it in
// that half's first third, so the cell scans on for a while after it.
inline void inject_once(FaultInjectionSettings& settings, InjectedFault fault,
                        std::int64_t last_profile, int profiles) {
  FaultSchedule* schedules[] = {&settings.frame_gaps,       &settings.camera_stalls,
                                &settings.encoder_glitches, &settings.encoder_reversals,
                                &settings.encoder_stuck,    &settings.laser_off,
                                &settings.photo_eye_bounces};
  const int every = static_cast<int>((last_profile + 2) / 2);
  *schedules[static_cast<int>(fault)] = {.every_profiles = every, .profiles = profiles};
  for (settings.seed = 1; settings.seed < 1000; ++settings.seed)
    if (FaultPlan(settings).occurrence_start(fault, every) < every + every / 3) return;
}

// Counts the FAULT statuses it keeps.
class FaultWatchingPublisher final : public Publisher {
 public:
  bool publish(const PartPose& pose) override { return memory.publish(pose); }
  bool publish(const Profile& profile) override { return memory.publish(profile); }
  bool publish(const CellStatus& status) override {
    if (status.state == CellState::kFault) faults.fetch_add(1);
    return memory.publish(status);
  }
  MemoryPublisher memory;
  std::atomic<int> faults{0};
};

// The checked source, slowed after a fault until a FAULT status went out (at most 3 s).
class SlowAfterFaultSource final : public ScannerSource {
 public:
  // `loop`: its dropped parts are a fault too (the overloaded recognizer's).
  SlowAfterFaultSource(StreamCheckedSource& source, const ScanLoop& loop,
                       const std::atomic<int>& faults_published)
      : source_(source), loop_(loop), faults_published_(faults_published) {}
  SourceStatus start() override { return source_.start(); }
  void reserve(Profile& profile) const override { source_.reserve(profile); }
  SourceStatus next(Profile& out) noexcept override {
    if (waiting_ && faults_published_.load() > faults_at_fault_) waiting_ = false;
    if (waiting_ && slowed_ms_ < 3000) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      ++slowed_ms_;
    }
    const SourceStatus status = source_.next(out);
    const std::uint64_t total = fault_total(source_.health()) +
                                static_cast<std::uint64_t>(loop_.counters().parts_dropped.load());
    if (total > last_total_ && !waiting_) {
      waiting_ = true;
      faults_at_fault_ = faults_published_.load();
    }
    last_total_ = total;
    return status;
  }
  void stop() noexcept override { source_.stop(); }
  double mm_per_profile() const override { return source_.mm_per_profile(); }
  std::string_view last_error() const noexcept override { return source_.last_error(); }
  SourceHealth health() const noexcept override { return source_.health(); }

 private:
  static std::uint64_t fault_total(const SourceHealth& h) {
    return h.profiles_lost + h.camera_timeouts + h.encoder_errors + h.encoder_reversals +
           h.gpio_edges_lost + h.photo_eye_bounces + h.encoder_stalls + h.laser_off_profiles;
  }
  StreamCheckedSource& source_;
  const ScanLoop& loop_;
  const std::atomic<int>& faults_published_;
  std::uint64_t last_total_ = 0;
  bool waiting_ = false;
  int faults_at_fault_ = 0;
  int slowed_ms_ = 0;
};

struct FaultCellRun {
  CellRunSummary summary;
  std::vector<PartRecognition> recognitions;
  std::vector<std::string> truths;  // the part scanned in each recognition's rows, "" none
  std::vector<CellStatus> statuses;

  std::int64_t total(const char* name) const {
    std::int64_t value = -1;
    CellStatus::visit_totals(summary.last_status,
                             [&](const char* key, std::int64_t total, const char*) {
                               if (std::string(key) == name) value = total;
                             });
    return value;
  }
  bool faulted_with(const std::string& words) const {
    for (const CellStatus& status : statuses)
      if (status.state == CellState::kFault && status.state_text.find(words) != std::string::npos)
        return true;
    return false;
  }
  int correct() const {
    int count = 0;
    for (std::size_t i = 0; i < recognitions.size(); ++i)
      count += recognitions[i].pose.status == PoseStatus::kOk &&
               recognitions[i].pose.part_name == truths[i];
    return count;
  }
  int wrong_ok() const {
    int count = 0;
    for (std::size_t i = 0; i < recognitions.size(); ++i)
      count += recognitions[i].pose.status == PoseStatus::kOk &&
               recognitions[i].pose.part_name != truths[i];
    return count;
  }
  // Every pose, for a failure message.
  std::string describe() const {
    std::string text;
    for (std::size_t i = 0; i < recognitions.size(); ++i) {
      const PartPose& pose = recognitions[i].pose;
      text += "\n  part " + std::to_string(pose.part_seq) + " rows " +
              std::to_string(recognitions[i].first_profile) + ".." +
              std::to_string(recognitions[i].last_profile) + " truth '" + truths[i] +
              "': " + to_string(pose.status) + " " + pose.part_name + " " + pose.reason;
    }
    return text;
  }
  int errors() const {
    int count = 0;
    for (const PartRecognition& r : recognitions) count += r.pose.status == PoseStatus::kError;
    return count;
  }
};

// `source` (not started) is checked and run; `truth` names the part in a row range.
inline FaultCellRun run_faulty_cell(
    std::unique_ptr<ScannerSource> source, const ScannerParameters& parameters,
    const std::function<std::string(std::int64_t, std::int64_t)>& truth,
    int recognizer_delay_ms = 0, int builders = 8) {
  static const ModelBase base = read_model_base(regression_model_base());
  static const Recognizer recognizer(base, CosmosParameters{}, RecognitionParameters{});
  StreamCheckedSource checked(std::move(source), parameters.encoder_ticks_per_profile);
  FaultCellRun run;
  if (checked.start() != SourceStatus::kOk) {
    run.summary.source_error = std::string(checked.last_error());
    return run;
  }
  ScanLoopSettings loop_settings;
  loop_settings.wait_for_recognizer = recognizer_delay_ms == 0;
  loop_settings.parts.builders = builders;
  loop_settings.parts.part_queue_slots = builders;
  ScanLoop loop(loop_settings);
  PartRecognitionContext context;
  context.recognizer = &recognizer;
  context.model_base = &base;
  context.mm_per_tick = parameters.encoder_mm_per_tick;
  context.x0_loop_mm = loop.x0_loop_mm();
  context.stream_faults = &checked.faults();
  CellRunSettings settings;
  settings.paced = false;
  settings.deterministic_output = true;
  settings.publishing.status_period_s = 0.001;
  settings.recognizer_delay_ms = recognizer_delay_ms;
  FaultWatchingPublisher publisher;
  SlowAfterFaultSource slowed(checked, loop, publisher.faults);
  run.summary =
      run_cell(slowed, loop, context, publisher, settings, [&](const PartRecognition& recognition) {
        run.recognitions.push_back(recognition);
        run.truths.push_back(truth(recognition.first_profile, recognition.last_profile));
      });
  checked.stop();
  run.statuses = publisher.memory.statuses;
  return run;
}

}  // namespace cosmos::testing
