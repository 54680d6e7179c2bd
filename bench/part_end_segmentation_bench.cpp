// The CSMP segmentation left at a part's end, on the views of a simulated stream's parts
// (640-point profiles, bench/sim_stream.hpp) cut out of their builders:
//   PartEndSegmentation
//                     searched in the view (segment_csmps) against grown from the seeds the
//                     builder found row by row (RowSeeds::view_seeds, then
//                     segment_csmps_from_seeds)
// Needs the catalog meshes (scripts/fetch_catalog.sh). Run: build/bench/part_end_segmentation_bench
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bench/sim_stream.hpp"
#include "core/segmentation/csmp_segmentation.hpp"
#include "core/segmentation/shape_seeds.hpp"
#include "firmware_bridge/kernel_timestamp.hpp"
#include "realtime/cell/part_recognition.hpp"
#include "realtime/loop/scan_loop.hpp"

namespace cosmos {
namespace {

using bench::median;
using bench::sim_stream;
using bench::SimStream;

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

}  // namespace
}  // namespace cosmos
