// Chapter-6 registration of one view pair (Table 6.1's 5 deg about x + 10 deg about z, from
// the identity, 0.03 mm noise): ~2,250 scene control points onto a model with a control point
// per pixel, Chen-Medioni and minimum-variance; plus building the control points.
// Run: build/bench/registration_bench --benchmark_repetitions=9 --benchmark_report_aggregates_only
// and read the medians (the machine is shared).
#include <benchmark/benchmark.h>

#include "core/registration/registration_points.hpp"
#include "core/registration/view_registration.hpp"
#include "sim/free_form_view_pair.hpp"

namespace cosmos {
namespace {

struct ViewPair {
  RangeImage model_image, scene_image;
  RegistrationPoints model, scene;
};

const ViewPair& view_pair() {
  static const ViewPair pair = [] {
    ViewPair p;
    p.model_image = render_free_form_part(RigidTransform::identity(), FreeFormPartSpec{});
    p.scene_image = render_free_form_part(
        {rotation_from_xyz_angles_deg(5, 0, 10), {1.5, -1.0, 0.8}}, FreeFormPartSpec{});
    add_z_noise(p.model_image, 0.03, 1);
    add_z_noise(p.scene_image, 0.03, 2);
    p.model = build_registration_points(p.model_image, {.stride_px = 1}).points;
    p.scene = build_registration_points(p.scene_image, {.stride_px = 2}).points;
    return p;
  }();
  return pair;
}

void register_pair(benchmark::State& state, RegistrationEstimator estimator) {
  const ViewPair& pair = view_pair();
  RegistrationParameters parameters;
  parameters.estimator = estimator;
  RegistrationResult result;
  for (auto _ : state) {
    result = register_views(pair.scene, pair.model, RigidTransform::identity(), parameters);
    benchmark::DoNotOptimize(result.T_model_scene.rotation.data());
  }
  state.counters["control_points"] = pair.scene.size();
  state.counters["iterations"] = result.iterations;
  state.counters["converged"] = result.converged ? 1 : 0;
  state.counters["intersection_steps"] = static_cast<double>(result.intersection_steps);
}

void BM_RegisterChenMedioni(benchmark::State& state) {
  register_pair(state, RegistrationEstimator::kChenMedioni);
}
BENCHMARK(BM_RegisterChenMedioni)->Unit(benchmark::kMillisecond);

void BM_RegisterMinimumVariance(benchmark::State& state) {
  register_pair(state, RegistrationEstimator::kMinimumVariance);
}
BENCHMARK(BM_RegisterMinimumVariance)->Unit(benchmark::kMillisecond);

void BM_BuildSceneControlPoints(benchmark::State& state) {
  const ViewPair& pair = view_pair();
  for (auto _ : state) {
    auto result = build_registration_points(pair.scene_image, {.stride_px = 2});
    benchmark::DoNotOptimize(result.points.position_mm.data());
  }
}
BENCHMARK(BM_BuildSceneControlPoints)->Unit(benchmark::kMillisecond);

void BM_BuildModelSurface(benchmark::State& state) {
  const ViewPair& pair = view_pair();
  for (auto _ : state) {
    auto result = build_registration_points(pair.model_image, {.stride_px = 1});
    benchmark::DoNotOptimize(result.points.position_mm.data());
  }
  state.counters["points"] = pair.model.size();
}
BENCHMARK(BM_BuildModelSurface)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cosmos
