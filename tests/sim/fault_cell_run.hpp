#pragma once
// The cell run over one faulty source that the fault-injection tests share: catalog parts of
// config/parts-regression.yaml on the simulated belt, the regression model base, the stream
// checker every cell source passes through, unpaced (every part recognized), and a status
// every millisecond so that a fault shows as FAULT while the run goes on. What comes back:
// the summary, every pose with its ground truth, and every status sent.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
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
  MemoryPublisher publisher;
  run.summary = run_cell(
      checked, loop, context, publisher, settings, [&](const PartRecognition& recognition) {
        run.recognitions.push_back(recognition);
        run.truths.push_back(truth(recognition.first_profile, recognition.last_profile));
      });
  checked.stop();
  run.statuses = publisher.statuses;
  return run;
}

}  // namespace cosmos::testing
