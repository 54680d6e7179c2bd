// Recognition (core/recognition/recognizer.hpp) stage by stage, on the seeded simulated scans of
// bench/recognition_scan_set.hpp (regression catalog, 5-part x 80-view base), so a reader sees
// where the time of one recognition goes; then the whole recognizer, with and without the
// features (the real-time cell builds them incrementally and pays only recognize_analyzed).
// Each iteration goes over every scan; the Time column is the whole set, the counters are per
// scan (median_ms / min_ms / max_ms over the scans of each scan's median: one scan that falls
// back to the pose search costs several times the others). Counters are in ms; the console
// prints small ones with SI prefixes (1.5m ms = 1.5 us).
// Run: build/bench/recognition_bench (the set-up recognizes every scan once, stage by stage).
#include <benchmark/benchmark.h>

#include <vector>

#include "bench/recognition_scan_set.hpp"
#include "core/modelbase/model_surface.hpp"
#include "core/recognition/part_pose_search.hpp"
#include "core/recognition/part_support.hpp"
#include "core/recognition/pose_hypotheses.hpp"
#include "core/recognition/recognizer.hpp"

namespace cosmos::bench {
namespace {

void BM_Features(benchmark::State& state) {
  const RecognitionScanSet* fixture = ready_scan_set(state);
  if (!fixture) return;
  // One workspace over the run of scans, as `cosmos eval` and the cell's part builders keep.
  ViewAnalysisWorkspace workspace;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(analyze_view(scan.image, fixture->cosmos(), workspace).moments);
  });
}
BENCHMARK(BM_Features)->Unit(benchmark::kMillisecond)->Iterations(10);

void BM_RegistrationControlPoints(benchmark::State& state) {
  const RecognitionScanSet* fixture = ready_scan_set(state);
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
  const RecognitionScanSet* fixture = ready_scan_set(state);
  if (!fixture) return;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(fixture->recognizer().selector().select(scan.analysis.moments));
  });
}
BENCHMARK(BM_SpectralSelection)->Unit(benchmark::kMillisecond)->Iterations(1000);

// §5.3 on each of the selected views: patch-group matching and the pose it implies.
void BM_PatchGroupMatchingAndPose(benchmark::State& state) {
  const RecognitionScanSet* fixture = ready_scan_set(state);
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
  const RecognitionScanSet* fixture = ready_scan_set(state);
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
// ranked and aligned against the part's distance field as verification does.
void BM_FieldAlignedStarts(benchmark::State& state) {
  const RecognitionScanSet* fixture = ready_scan_set(state);
  if (!fixture) return;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    for (const SelectedView& selected : scan.selected)
      benchmark::DoNotOptimize(fixture->field_aligned_starts(scan, selected));
  });
}
BENCHMARK(BM_FieldAlignedStarts)->Unit(benchmark::kMillisecond)->Iterations(20);

// One minimum-variance registration from the chosen view's best initial pose; the recognizer
// runs registered_hypotheses of these per selected view.
void BM_OneRegistration(benchmark::State& state) {
  const RecognitionScanSet* fixture = ready_scan_set(state);
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
  const RecognitionScanSet* fixture = ready_scan_set(state);
  if (!fixture) return;
  const RecognitionParameters& parameters = fixture->parameters();
  over_scans(state, *fixture, [&](const TestScan& scan) {
    ModelSurfaces surfaces(
        fixture->base(),
        fixture->parameters().surfaces);  // as a recognition's first measurement: cold
    const int part = fixture->base().views[static_cast<std::size_t>(scan.chosen_view)].part_index;
    benchmark::DoNotOptimize(measure_part_support(
        scan.scene_points, fixture->base(), fixture->recognizer().part_search_model(part).views,
        scan.chosen_view, scan.chosen_registered, parameters.registration, parameters.support,
        surfaces));
  });
}
BENCHMARK(BM_PartSupport)->Unit(benchmark::kMillisecond)->Iterations(50);

// The fallback, for one part (the recognizer searches up to `searched_parts` of them, and
// only when no selected view registers with enough support).
void BM_FallbackPoseSearchOnePart(benchmark::State& state) {
  const RecognitionScanSet* fixture = ready_scan_set(state);
  if (!fixture) return;
  const RecognitionParameters& parameters = fixture->parameters();
  over_scans(state, *fixture, [&](const TestScan& scan) {
    ModelSurfaces surfaces(
        fixture->base(),
        fixture->parameters().surfaces);  // cold, as the recognition's first search
    benchmark::DoNotOptimize(
        search_part_pose(scan.scene_points, fixture->base(),
                         fixture->recognizer().part_search_model(scan.searched_part),
                         parameters.registration, parameters.search, surfaces));
  });
}
BENCHMARK(BM_FallbackPoseSearchOnePart)->Unit(benchmark::kMillisecond)->Iterations(5);

// The quick field fit that orders the search over every part (catalog_rank), for every part
// of the base: the one cost of a search that grows with the catalog whatever the scan.
void BM_QuickFieldFitEveryPart(benchmark::State& state) {
  const RecognitionScanSet* fixture = ready_scan_set(state);
  if (!fixture) return;
  const RecognitionParameters& parameters = fixture->parameters();
  const int parts = static_cast<int>(fixture->base().parts.size());
  over_scans(state, *fixture, [&](const TestScan& scan) {
    const QuickFitPoints points = quick_fit_points(scan.scene_points, parameters.catalog_rank);
    for (int part = 0; part < parts; ++part)
      benchmark::DoNotOptimize(quick_field_poses(points, fixture->base(),
                                                 fixture->recognizer().part_search_model(part),
                                                 parameters.search, parameters.catalog_rank));
  });
}
BENCHMARK(BM_QuickFieldFitEveryPart)->Unit(benchmark::kMillisecond)->Iterations(20);

void report_outcomes(benchmark::State& state, const RecognitionScanSet& fixture) {
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
  const RecognitionScanSet* fixture = ready_scan_set(state);
  if (!fixture) return;
  ViewAnalysisWorkspace workspace;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(fixture->recognizer().recognize(scan.image, workspace).part);
  });
  report_outcomes(state, *fixture);
}
BENCHMARK(BM_Recognize)->Unit(benchmark::kMillisecond)->Iterations(5);

// What the real-time cell pays once the scan's features exist.
void BM_RecognizeAnalyzed(benchmark::State& state) {
  const RecognitionScanSet* fixture = ready_scan_set(state);
  if (!fixture) return;
  over_scans(state, *fixture, [&](const TestScan& scan) {
    benchmark::DoNotOptimize(
        fixture->recognizer().recognize_analyzed(scan.image, scan.analysis).part);
  });
  report_outcomes(state, *fixture);
}
BENCHMARK(BM_RecognizeAnalyzed)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace
}  // namespace cosmos::bench
