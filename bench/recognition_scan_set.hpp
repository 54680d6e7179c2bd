#pragma once
// The recognition bench's scan set: the first kScans test scans `cosmos eval --seed 11` makes
// of the regression catalog (sim/evaluation/evaluation_scans.hpp), against the regression model
// base
// ($COSMOS_BENCH_MODEL_BASE, default <build>/test-data/regression-80.cmb, which ctest's
// build_regression_model_base makes; catalog $COSMOS_BENCH_CATALOG, default
// config/parts-regression.yaml), each with the output of every recognition stage computed
// once, so that a benchmark times one stage on its real inputs. And the per-scan timing the
// benchmarks report: each scan's median over the iterations, then median / min / max over
// the scans.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/model_base_file.hpp"
#include "core/modelbase/model_surface.hpp"
#include "core/recognition/pose_hypotheses.hpp"
#include "core/recognition/recognizer.hpp"
#include "core/representation/cosmos_pipeline.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/evaluation/evaluation_scans.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos::bench {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

inline constexpr int kScans = 10;
inline constexpr std::uint64_t kScanSeed = 11;  // the recognition regression suite's eval seed
inline constexpr const char* kDefaultModelBase = COSMOS_REGRESSION_MODEL_BASE;

inline double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

inline double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + middle, values.end());
  if (values.size() % 2 == 1) return values[middle];
  const double upper = values[middle];
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + middle));
}

inline std::string environment_or(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? std::string(value) : fallback;
}

inline fs::path regression_catalog_path() {
  const std::string path = environment_or("COSMOS_BENCH_CATALOG", "");
  if (!path.empty()) return path;
  return find_part_catalog().parent_path() / "parts-regression.yaml";
}

// Wall time per scan, kept per scan so the counters can be medians over the scans.
class ScanTimes {
 public:
  explicit ScanTimes(std::size_t scans) : samples_ms_(scans) {}

  template <typename Work>
  void time(std::size_t scan, Work&& work) {
    const Clock::time_point start = Clock::now();
    work();
    samples_ms_[scan].push_back(elapsed_ms(start));
  }

  void report(benchmark::State& state) const {
    std::vector<double> per_scan_ms;
    for (const std::vector<double>& samples : samples_ms_)
      if (!samples.empty()) per_scan_ms.push_back(median(samples));
    if (per_scan_ms.empty()) return;
    state.counters["median_ms"] = median(per_scan_ms);
    state.counters["min_ms"] = *std::min_element(per_scan_ms.begin(), per_scan_ms.end());
    state.counters["max_ms"] = *std::max_element(per_scan_ms.begin(), per_scan_ms.end());
  }

 private:
  std::vector<std::vector<double>> samples_ms_;
};

// One §5.2-selected model view of a scan, with what the stages before the one being timed

struct SelectedView {
  int view = -1;
  PatchGroupMatch match;
  PoseFromPatches from_patches;
  RegistrationPoints model;  // its model surface, unpacked once here
};

struct TestScan {
  std::string part_name;
  int true_part = -1;  // ModelBase::parts index
  RangeImage image;
  ViewAnalysis analysis;
  RegistrationPoints scene_points;
  std::vector<SelectedView> selected;
  RecognitionResult recognition;  // one untimed run, to know what the recognizer decided
  bool fell_back = false;         // the recognizer needed the pose search
  int searched_part = -1;         // the first part the pose search would search
  // Registration and part support are timed on the view the recognizer chose (the spectrally
  // closest one when it rejected the scan), from that view's best-ranked initial pose.
  int chosen_view = -1;
  RegistrationPoints chosen_model;
  RigidTransform chosen_start;
  RigidTransform chosen_registered;
};

class RecognitionScanSet {
 public:
  RecognitionScanSet() {
    const fs::path base_path = environment_or("COSMOS_BENCH_MODEL_BASE", kDefaultModelBase);
    try {
      base_ = read_model_base(base_path);
    } catch (const std::exception& error) {
      error_ =
          std::string("cannot read the model base (set COSMOS_BENCH_MODEL_BASE): ") + error.what();
      return;
    }
    try {
      make_scans();
    } catch (const std::exception& error) {
      error_ = std::string("cannot make the test scans: ") + error.what();
    }
  }

  const std::string& error() const { return error_; }
  const ModelBase& base() const { return base_; }
  const CosmosParameters& cosmos() const { return cosmos_; }
  const RecognitionParameters& parameters() const { return parameters_; }

  // Verification's starts on one selected view (Recognizer::verify).
  std::vector<ViewPoseHypothesis> field_aligned_starts(const TestScan& scan,
                                                       const SelectedView& selected) const {
    const std::vector<RigidTransform> generated =
        generate_pose_hypotheses(scan.scene_points, selected.model, selected.from_patches,
                                 {.in_plane_turns = parameters_.in_plane_hypotheses});
    const int part = base_.views[static_cast<std::size_t>(selected.view)].part_index;
    return align_view_starts_in_field(
        scan.scene_points, base_, selected.view, generated, recognizer_->part_search_model(part),
        parameters_.field_starts, parameters_.search, parameters_.registered_hypotheses);
  }
  const Recognizer& recognizer() const { return *recognizer_; }
  const std::vector<TestScan>& scans() const { return scans_; }

 private:
  void make_scans() {
    const ScannerParameters scanner;
    // The scans' scanner, as `cosmos eval` tells its recognizer.
    parameters_.surface_seen.sight = scanner_sight(scanner);
    recognizer_ = std::make_unique<Recognizer>(base_, cosmos_, parameters_);
    const std::vector<EvaluationPart> parts =
        evaluation_parts(base_, read_part_catalog(regression_catalog_path()), {});
    for (const EvaluationTest& test : evaluation_plan(parts, kScans, kScanSeed)) {
      const EvaluationPart& part = parts[static_cast<std::size_t>(test.part)];
      TestScan scan;
      scan.part_name = part.name;
      scan.true_part = part.base_index;
      scan.image = scan_evaluation_test(test, parts, scanner, ConditioningParameters{});
      if (scan.image.width() == 0 || scan.image.count_valid() == 0) continue;
      prepare_stages(scan);
      if (scan.scene_points.size() < parameters_.min_scene_points || scan.selected.empty())
        continue;
      scans_.push_back(std::move(scan));
    }
    if (scans_.empty()) throw std::runtime_error("no scan has enough surface to recognize");
  }

  // Runs the stages once, as Recognizer::recognize_analyzed does, keeping each one's output.
  void prepare_stages(TestScan& scan) const {
    scan.analysis = analyze_view(scan.image, cosmos_);
    scan.scene_points =
        build_registration_points(scan.image, parameters_.scene_points, &scan.analysis.frames)
            .points;
    for (const SpectralCandidate& candidate :
         recognizer_->selector().select(scan.analysis.moments)) {
      const ModelBaseView& view = base_.views[static_cast<std::size_t>(candidate.view)];
      SelectedView selected;
      selected.view = candidate.view;
      selected.match = match_patch_groups(scan.analysis.view, view.cosmos, parameters_.matching);
      selected.from_patches = estimate_pose_from_patches(scan.analysis.view, view.cosmos,
                                                         selected.match.pairs, parameters_.pose);
      selected.model = ModelSurface(view).points();
      scan.selected.push_back(std::move(selected));
    }
    if (scan.selected.empty()) return;

    scan.recognition = recognizer_->recognize_analyzed(scan.image, scan.analysis);
    scan.fell_back =
        std::any_of(scan.recognition.candidates.begin(), scan.recognition.candidates.end(),
                    [](const RecognitionCandidate& c) { return c.from_pose_search; });
    const std::vector<int> parts = recognizer_->selector().rank_parts(scan.analysis.moments);
    if (!parts.empty()) scan.searched_part = parts.front();

    scan.chosen_view =
        scan.recognition.view >= 0 ? scan.recognition.view : scan.selected.front().view;
    const ModelBaseView& view = base_.views[static_cast<std::size_t>(scan.chosen_view)];
    scan.chosen_model = ModelSurface(view).points();
    const PatchGroupMatch match =
        match_patch_groups(scan.analysis.view, view.cosmos, parameters_.matching);
    const PoseFromPatches from_patches =
        estimate_pose_from_patches(scan.analysis.view, view.cosmos, match.pairs, parameters_.pose);
    SelectedView chosen;
    chosen.view = scan.chosen_view;
    chosen.from_patches = from_patches;
    chosen.model = scan.chosen_model;
    const std::vector<ViewPoseHypothesis> starts = field_aligned_starts(scan, chosen);
    if (!starts.empty()) {
      // Registered on the view the start was moved to.
      scan.chosen_view = starts.front().view;
      scan.chosen_model =
          ModelSurface(base_.views[static_cast<std::size_t>(scan.chosen_view)]).points();
      scan.chosen_start = starts.front().T_model_scene;
    }
    scan.chosen_registered = register_views(scan.scene_points, scan.chosen_model, scan.chosen_start,
                                            parameters_.registration)
                                 .T_model_scene;
  }

  std::string error_;
  ModelBase base_;
  CosmosParameters cosmos_;
  RecognitionParameters parameters_;
  std::unique_ptr<Recognizer> recognizer_;
  std::vector<TestScan> scans_;
};

// Built on first use, in place (the recognizer keeps a reference to the base).
inline const RecognitionScanSet* ready_scan_set(benchmark::State& state) {
  static const RecognitionScanSet fixture;
  if (!fixture.error().empty()) {
    state.SkipWithError(fixture.error().c_str());
    return nullptr;
  }
  return &fixture;
}

// Runs `work(scan)` on every scan per iteration, timing each scan.
template <typename Work>
void over_scans(benchmark::State& state, const RecognitionScanSet& fixture, Work&& work) {
  const std::vector<TestScan>& scans = fixture.scans();
  ScanTimes times(scans.size());
  for (auto _ : state)
    for (std::size_t s = 0; s < scans.size(); ++s) times.time(s, [&] { work(scans[s]); });
  times.report(state);
  state.counters["scans"] = static_cast<double>(scans.size());
}

}  // namespace cosmos::bench
