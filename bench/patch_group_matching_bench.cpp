// COSMOS view verification (§5.3): patch-group graph matching of two views and the initial
// pose from the correspondence (target: a match of two 15-patch views well under 1 ms).
// Run: build/bench/patch_group_matching_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "core/matching/patch_group_matching.hpp"
#include "core/matching/pose_from_patches.hpp"
#include "tests/core/matching_fixture.hpp"

namespace cosmos {
namespace {

// A 3 x 5 grid of patches with 4-neighbour adjacency: denser than the patch graphs of real
// views (more cycles, more ways to split), so a worst case for 15 patches.
CosmosView grid_view(double jitter) {
  constexpr int kRows = 3;
  constexpr int kColumns = 5;
  CosmosView view;
  for (int k = 0; k < kRows * kColumns; ++k) {
    const int row = k / kColumns;
    const int column = k % kColumns;
    Csmp patch;
    patch.id = k;
    const double wiggle = jitter * std::sin(3.7 * k + 1.0);
    patch.area_mm2 = 100 + 37 * ((k * 7) % 5) + 10 * wiggle;
    patch.shape_index = 0.1 + 0.1 * ((k * 5) % 9) + 0.01 * wiggle;
    patch.mean_curvedness_per_mm = 0.05;
    patch.pixels = 400;
    if (row > 0) patch.neighbors.push_back({k - kColumns, 20});
    if (row + 1 < kRows) patch.neighbors.push_back({k + kColumns, 20});
    if (column > 0) patch.neighbors.push_back({k - 1, 20});
    if (column + 1 < kColumns) patch.neighbors.push_back({k + 1, 20});
    view.patches.push_back(patch);
  }
  return view;
}

// The relief of the tests segmented finely (fixed shape diameter, small patches kept).
const CosmosView& fine_relief_view(int turn_deg) {
  static std::map<int, CosmosView> cache;
  auto found = cache.find(turn_deg);
  if (found != cache.end()) return found->second;
  CosmosParameters parameters;
  parameters.segmentation.max_patches = 0;
  parameters.segmentation.shape_diameter_limit = 0.15;
  parameters.segmentation.min_patch_area_fraction = 0.01;
  const RangeImage image = testing::make_relief_range_image(turn_deg, 0.01, 7 + turn_deg);
  return cache.emplace(turn_deg, analyze_view(image, parameters).view).first->second;
}

void run_match(benchmark::State& state, const CosmosView& scene, const CosmosView& model) {
  PatchGroupMatch match;
  for (auto _ : state) {
    match = match_patch_groups(scene, model);
    benchmark::DoNotOptimize(match.score);
  }
  state.counters["scene_patches"] = static_cast<double>(scene.patches.size());
  state.counters["model_patches"] = static_cast<double>(model.patches.size());
  state.counters["score"] = match.score;
  state.counters["operations"] = static_cast<double>(match.operations);
}

void BM_MatchCapsuleViews(benchmark::State& state) {
  run_match(state, testing::analytic_view(AnalyticShape::kCapsule, 35).view,
            testing::analytic_view(AnalyticShape::kCapsule, 0).view);
}
BENCHMARK(BM_MatchCapsuleViews)->Unit(benchmark::kMicrosecond);

void BM_MatchCapsuleAgainstTorus(benchmark::State& state) {
  run_match(state, testing::analytic_view(AnalyticShape::kCapsule, 35).view,
            testing::analytic_view(AnalyticShape::kTorus, 0).view);
}
BENCHMARK(BM_MatchCapsuleAgainstTorus)->Unit(benchmark::kMicrosecond);

void BM_MatchReliefViews(benchmark::State& state) {
  run_match(state, testing::relief_view(40).view, testing::relief_view(0).view);
}
BENCHMARK(BM_MatchReliefViews)->Unit(benchmark::kMicrosecond);

void BM_MatchFinelySegmentedReliefViews(benchmark::State& state) {
  run_match(state, fine_relief_view(40), fine_relief_view(0));
}
BENCHMARK(BM_MatchFinelySegmentedReliefViews)->Unit(benchmark::kMicrosecond);

void BM_MatchFifteenPatchGrids(benchmark::State& state) {
  static const CosmosView scene = grid_view(1.0);
  static const CosmosView model = grid_view(-1.0);
  run_match(state, scene, model);
}
BENCHMARK(BM_MatchFifteenPatchGrids)->Unit(benchmark::kMicrosecond);

void BM_PoseFromReliefCorrespondence(benchmark::State& state) {
  const CosmosView& scene = testing::relief_view(40).view;
  const CosmosView& model = testing::relief_view(0).view;
  const PatchGroupMatch match = match_patch_groups(scene, model);
  for (auto _ : state) {
    const PoseFromPatches pose = estimate_pose_from_patches(scene, model, match.pairs);
    benchmark::DoNotOptimize(pose.T_model_scene.rotation.data());
  }
}
BENCHMARK(BM_PoseFromReliefCorrespondence)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmos
