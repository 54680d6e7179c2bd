// The model-base build (sim/model_base_build/model_base_builder.hpp, what `cosmos modelbase build`
// runs) of one regression part from the 20 icosahedron face centres (--views 20), on one thread:
// the mesh, the simulated scans, the chapter-3 features and control points of every view, and the
// view grouping. The time is per part; divide by `views` for a view.
// Run: build/bench/model_base_build_bench (needs the catalog meshes, scripts/fetch_catalog.sh).
#include <benchmark/benchmark.h>

#include <exception>
#include <string>

#include "scanner/scanner_model.hpp"
#include "sim/model_base_build/model_base_builder.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos {
namespace {

void BM_ModelBaseBuildOnePart(benchmark::State& state) {
  PartCatalog catalog;
  try {
    catalog = read_part_catalog(find_part_catalog().parent_path() / "parts-regression.yaml");
  } catch (const std::exception& error) {
    state.SkipWithError((std::string("cannot read the catalog: ") + error.what()).c_str());
    return;
  }
  catalog.parts.resize(1);
  ModelBaseBuildSettings settings;
  settings.view_count = 20;
  settings.threads = 1;
  std::size_t views = 0;
  for (auto _ : state) {
    const ModelBase base = build_model_base(catalog, ScannerParameters{}, settings);
    views = base.views.size();
    benchmark::DoNotOptimize(base.clusters.data());
  }
  state.counters["views"] = static_cast<double>(views);
}
// Real time: the build runs on its worker thread, not the benchmark's.
BENCHMARK(BM_ModelBaseBuildOnePart)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();

}  // namespace
}  // namespace cosmos
