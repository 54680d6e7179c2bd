// Recognition (core/recognizer.hpp) stage by stage, on 10 seeded simulated scans of the
// regression catalog (config/parts-regression.yaml) against its 5-part x 80-view model base,
// so a reader sees where the time of one recognition goes; then the whole recognizer, with
// and without the features (the real-time cell builds them incrementally and pays only
// recognize_analyzed); then the model-base build of one part.
//
// The scans are the ones `cosmos eval --seed 11` would make (apps/evaluation_scans.cpp:
// test i scans known part mix_seed(11, 2^32 + i) mod 5 in a random pose and noise drawn from
// that seed), made before any timing. Each benchmark iteration goes over every scan; its Time
// column is the whole set, and the counters are per scan: each scan's median over the
// iterations, then median_ms / min_ms / max_ms over the scans (a median, because one scan
// that falls back to the pose search costs several times the others).
//
// The model base comes from $COSMOS_BENCH_MODEL_BASE, default
// <build>/test-data/regression-80.cmb (ctest's build_regression_model_base makes it);
// the catalog from $COSMOS_BENCH_CATALOG, default config/parts-regression.yaml of the source
// tree (found like the CLI finds config/parts.yaml).
// Counters are in ms; the console prints small ones with SI prefixes (1.5m ms = 1.5 us).
// Run: build/bench/recognition_bench (under a minute on 2 cores, setup included).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/cosmos_pipeline.hpp"
#include "core/io/model_base_file.hpp"
#include "core/model_surface.hpp"
#include "core/packed_registration_points.hpp"
#include "core/pose_hypotheses.hpp"
#include "core/recognizer.hpp"
#include "core/view_grouping.hpp"
#include "sim/mesh.hpp"
#include "sim/model_views.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_pose.hpp"
#include "sim/part_scan.hpp"
#include "sim/scanner_model.hpp"
#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kScans = 10;
constexpr std::uint64_t kScanSeed = 11;  // the recognition regression suite's eval seed
// Test scans draw from streams above 2^32 so they never share noise with the model views
// (apps/evaluation_scans.cpp, kTestStreamBase).
constexpr std::uint64_t kTestStreamBase = std::uint64_t{1} << 32;
constexpr const char* kDefaultModelBase = COSMOS_REGRESSION_MODEL_BASE;

// The model-base build: the 20 icosahedron face centres, which are the first 20 directions
// of `cosmos modelbase build --views N` (apps/view_direction_subset.hpp: direction 16 f + 15
// is the centre of face f), at the model surface's control-point stride of 3 px
// (apps/model_base_builder.hpp).
constexpr int kBuildViews = 20;
constexpr int kModelSurfaceStridePx = 3;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + middle, values.end());
  if (values.size() % 2 == 1) return values[middle];
  const double upper = values[middle];
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + middle));
}

std::string environment_or(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? std::string(value) : fallback;
}

fs::path regression_catalog_path() {
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
// produce for it.
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

class Fixture {
 public:
  Fixture() {
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
  const Recognizer& recognizer() const { return *recognizer_; }
  const std::vector<TestScan>& scans() const { return scans_; }

 private:
  void make_scans() {
    recognizer_ = std::make_unique<Recognizer>(base_, cosmos_, parameters_);
    const PartCatalog catalog = read_part_catalog(regression_catalog_path());
    std::map<std::string, TriangleMesh> meshes;
    const ScannerParameters scanner;
    for (int i = 0; i < kScans; ++i) {
      const std::uint64_t test_seed = mix_seed(kScanSeed, kTestStreamBase + i);
      const int part = static_cast<int>(test_seed % base_.parts.size());
      const std::string& name = base_.parts[static_cast<std::size_t>(part)].name;
      if (!meshes.contains(name)) {
        const PartEntry& entry = catalog.at(name);
        meshes.emplace(name, load_mesh(entry.mesh_path, entry.size_mm));
      }
      ScannerParameters noisy = scanner;
      noisy.seed = mix_seed(test_seed, 1);
      TestScan scan;
      scan.part_name = name;
      scan.true_part = part;
      scan.image =
          scan_single_part(meshes.at(name), name, random_rotation(mix_seed(test_seed, 0)), noisy);
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
    const std::vector<int> clusters = recognizer_->selector().rank_clusters(scan.analysis.moments);
    if (!clusters.empty())
      scan.searched_part = base_.clusters[static_cast<std::size_t>(clusters.front())].part_index;

    scan.chosen_view =
        scan.recognition.view >= 0 ? scan.recognition.view : scan.selected.front().view;
    const ModelBaseView& view = base_.views[static_cast<std::size_t>(scan.chosen_view)];
    scan.chosen_model = ModelSurface(view).points();
    const PatchGroupMatch match =
        match_patch_groups(scan.analysis.view, view.cosmos, parameters_.matching);
    const PoseFromPatches from_patches =
        estimate_pose_from_patches(scan.analysis.view, view.cosmos, match.pairs, parameters_.pose);
    const std::vector<PoseHypothesis> hypotheses = rank_pose_hypotheses(
        scan.scene_points, scan.chosen_model, from_patches, parameters_.registration,
        {.in_plane_turns = parameters_.in_plane_hypotheses});
    if (!hypotheses.empty()) scan.chosen_start = hypotheses.front().T_model_scene;
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
const Fixture* ready_fixture(benchmark::State& state) {
  static const Fixture fixture;
  if (!fixture.error().empty()) {
    state.SkipWithError(fixture.error().c_str());
    return nullptr;
  }
  return &fixture;
}

// Runs `work(scan)` on every scan per iteration, timing each scan.
template <typename Work>
void over_scans(benchmark::State& state, const Fixture& fixture, Work&& work) {
  const std::vector<TestScan>& scans = fixture.scans();
  ScanTimes times(scans.size());
  for (auto _ : state)
    for (std::size_t s = 0; s < scans.size(); ++s) times.time(s, [&] { work(scans[s]); });
  times.report(state);
  state.counters["scans"] = static_cast<double>(scans.size());
}

void BM_Features(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(analyze_view(scan.image, fixture->cosmos()).moments);
  });
}
BENCHMARK(BM_Features)->Unit(benchmark::kMillisecond)->Iterations(10);

void BM_RegistrationControlPoints(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  double points = 0;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    const RegistrationPointsResult result = build_registration_points(
        scan.image, fixture->parameters().scene_points, &scan.analysis.frames);
    points += result.points.size();
  });
  state.counters["points_per_scan"] =
      points / static_cast<double>(state.iterations() * fixture->scans().size());
}
BENCHMARK(BM_RegistrationControlPoints)->Unit(benchmark::kMillisecond)->Iterations(100);

void BM_SpectralSelection(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(fixture->recognizer().selector().select(scan.analysis.moments));
  });
}
BENCHMARK(BM_SpectralSelection)->Unit(benchmark::kMillisecond)->Iterations(1000);

// §5.3 on each of the selected views: patch-group matching and the pose it implies.
void BM_PatchGroupMatchingAndPose(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  const RecognitionParameters& parameters = fixture->parameters();
  over_scans(state, *fixture, [&](const TestScan& scan) {
    for (const SelectedView& selected : scan.selected) {
      const CosmosView& model =
          fixture->base().views[static_cast<std::size_t>(selected.view)].cosmos;
      const PatchGroupMatch match =
          match_patch_groups(scan.analysis.view, model, parameters.matching);
      benchmark::DoNotOptimize(
          estimate_pose_from_patches(scan.analysis.view, model, match.pairs, parameters.pose)
              .T_model_scene);
    }
  });
  state.counters["views_per_scan"] = parameters.selection.best_views;
}
BENCHMARK(BM_PatchGroupMatchingAndPose)->Unit(benchmark::kMillisecond)->Iterations(100);

// The recognizer unpacks each selected view's model surface from the base's compact form
// (counted in its registration time).
void BM_ModelSurfaceUnpack(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    for (const SelectedView& selected : scan.selected) {
      const ModelSurface model(fixture->base().views[static_cast<std::size_t>(selected.view)]);
      benchmark::DoNotOptimize(model.points().position_mm.data());
    }
  });
}
BENCHMARK(BM_ModelSurfaceUnpack)->Unit(benchmark::kMillisecond)->Iterations(100);

// The initial poses of each selected view (patch groups, principal axes, in-plane turns),
// each scored by one correspondence pass.
void BM_PoseHypothesisRanking(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  const RecognitionParameters& parameters = fixture->parameters();
  over_scans(state, *fixture, [&](const TestScan& scan) {
    for (const SelectedView& selected : scan.selected)
      benchmark::DoNotOptimize(rank_pose_hypotheses(
          scan.scene_points, selected.model, selected.from_patches, parameters.registration,
          {.in_plane_turns = parameters.in_plane_hypotheses}));
  });
}
BENCHMARK(BM_PoseHypothesisRanking)->Unit(benchmark::kMillisecond)->Iterations(20);

// One minimum-variance registration from the chosen view's best initial pose; the recognizer
// runs registered_hypotheses of these per selected view.
void BM_OneRegistration(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  double iterations = 0;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    const RegistrationResult result =
        register_views(scan.scene_points, scan.chosen_model, scan.chosen_start,
                       fixture->parameters().registration);
    iterations += result.iterations;
  });
  state.counters["icp_iterations_per_scan"] =
      iterations / static_cast<double>(state.iterations() * fixture->scans().size());
  state.counters["registrations_per_recognition"] =
      fixture->parameters().registered_hypotheses * fixture->parameters().selection.best_views;
}
BENCHMARK(BM_OneRegistration)->Unit(benchmark::kMillisecond)->Iterations(50);

// The chosen view's registered pose judged against the part's views around it.
void BM_PartSupport(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  const RecognitionParameters& parameters = fixture->parameters();
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(measure_part_support(
        scan.scene_points, fixture->base(), scan.chosen_view, scan.chosen_model,
        scan.chosen_registered, parameters.registration, parameters.support));
  });
}
BENCHMARK(BM_PartSupport)->Unit(benchmark::kMillisecond)->Iterations(50);

// The fallback, for one part (the recognizer searches up to `searched_parts` of them, and
// only when no selected view registers with enough support).
void BM_FallbackPoseSearchOnePart(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  const RecognitionParameters& parameters = fixture->parameters();
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(search_part_pose(scan.scene_points, fixture->base(),
                                              scan.searched_part, parameters.registration,
                                              parameters.search));
  });
}
BENCHMARK(BM_FallbackPoseSearchOnePart)->Unit(benchmark::kMillisecond)->Iterations(5);

void report_outcomes(benchmark::State& state, const Fixture& fixture) {
  int identified = 0, fell_back = 0;
  for (const TestScan& scan : fixture.scans()) {
    identified += scan.recognition.status == RecognitionStatus::kOk &&
                  scan.recognition.part == scan.true_part;
    fell_back += scan.fell_back;
  }
  state.counters["identified"] = identified;
  state.counters["fell_back"] = fell_back;
}

void BM_Recognize(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(fixture->recognizer().recognize(scan.image).part);
  });
  report_outcomes(state, *fixture);
}
BENCHMARK(BM_Recognize)->Unit(benchmark::kMillisecond)->Iterations(5);

// What the real-time cell pays once the scan's features exist.
void BM_RecognizeAnalyzed(benchmark::State& state) {
  const Fixture* fixture = ready_fixture(state);
  if (!fixture) return;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(
        fixture->recognizer().recognize_analyzed(scan.image, scan.analysis).part);
  });
  report_outcomes(state, *fixture);
}
BENCHMARK(BM_RecognizeAnalyzed)->Unit(benchmark::kMillisecond)->Iterations(5);

// build_model_base (apps/model_base_builder.cpp) is compiled only into the `cosmos`
// executable, not into a library a bench links, so this repeats its per-part work with the
// same calls on one thread: load the mesh, one scanner scene per part, and per view the
// profile scan, analyze_view, the model-surface control points and their packing; then the
// view grouping. Left out: the part's diameter (a convex hull and a farthest-pair search) and
// the parameters text.
void BM_ModelBaseBuildOnePart(benchmark::State& state) {
  PartCatalog catalog;
  try {
    catalog = read_part_catalog(regression_catalog_path());
  } catch (const std::exception& error) {
    state.SkipWithError((std::string("cannot read the catalog: ") + error.what()).c_str());
    return;
  }
  const PartEntry& entry = catalog.parts.front();
  const CosmosParameters cosmos;
  const ScannerParameters scanner;
  RegistrationPointParameters control_points;
  control_points.stride_px = kModelSurfaceStridePx;
  std::vector<double> view_ms, scan_ms, analysis_ms, control_points_ms;
  std::vector<double> mesh_ms, renderer_ms, grouping_ms;
  int views = 0;
  for (auto _ : state) {
    Clock::time_point stage = Clock::now();
    const TriangleMesh mesh = load_mesh(entry.mesh_path, entry.size_mm);
    mesh_ms.push_back(elapsed_ms(stage));
    stage = Clock::now();
    ModelViewRenderer renderer(mesh, entry.name, scanner);
    renderer_ms.push_back(elapsed_ms(stage));
    ModelBase base;
    base.parts.push_back(
        {entry.name, entry.mesh_path.filename().string(), entry.size_mm, 0, entry.symmetric});
    for (int face = 0; face < kBuildViews; ++face) {
      const int view_index = 16 * face + 15;
      const Clock::time_point view_start = Clock::now();
      stage = view_start;
      const ModelView scanned = renderer.scan_view(view_index);
      scan_ms.push_back(elapsed_ms(stage));
      if (scanned.image.width() == 0 || scanned.image.count_valid() == 0) continue;
      stage = Clock::now();
      ViewAnalysis analysis = analyze_view(scanned.image, cosmos);
      analysis_ms.push_back(elapsed_ms(stage));
      stage = Clock::now();
      ModelBaseView view;
      view.part_index = 0;
      view.view_index = view_index;
      view.direction_part = scanned.direction_part;
      view.T_scanner_part = {scanned.T_scanner_part.linear(), scanned.T_scanner_part.translation()};
      view.moments = analysis.moments;
      view.registration_packed = pack_registration_points(
          build_registration_points(scanned.image, control_points, &analysis.frames).points);
      control_points_ms.push_back(elapsed_ms(stage));
      view.cosmos = std::move(analysis.view);
      base.views.push_back(std::move(view));
      view_ms.push_back(elapsed_ms(view_start));
    }
    stage = Clock::now();
    const ViewGroupingResult grouping = group_model_views(base, ViewGroupingParameters{});
    grouping_ms.push_back(elapsed_ms(stage));
    benchmark::DoNotOptimize(grouping.clusters.data());
    views = static_cast<int>(base.views.size());
  }
  state.counters["views"] = views;
  state.counters["median_view_ms"] = median(view_ms);
  state.counters["scan_median_ms"] = median(scan_ms);
  state.counters["features_median_ms"] = median(analysis_ms);
  state.counters["control_points_median_ms"] = median(control_points_ms);
  state.counters["mesh_load_median_ms"] = median(mesh_ms);
  state.counters["scanner_scene_median_ms"] = median(renderer_ms);
  state.counters["grouping_median_ms"] = median(grouping_ms);
}
BENCHMARK(BM_ModelBaseBuildOnePart)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace
}  // namespace cosmos
