#pragma once
// The simulated streams the real-time benches time (scan_loop_bench.cpp,
// part_end_segmentation_bench.cpp): the regression catalog (or $COSMOS_BENCH_CATALOG), whole
// streams of its parts pre-generated in memory so that timed loops run no ray casting, and
// the quantiles their counters report.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/profile.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_source.hpp"

namespace cosmos::bench {

// Parts in the pre-generated streams: enough part rows, part ends and empty belt between them
// for a p99.9 over a few thousand profiles, few enough to generate 3200-point streams quickly.
constexpr int kStreamParts = 5;
constexpr std::uint64_t kSeed = 7;

// The regression catalog, or $COSMOS_BENCH_CATALOG (e.g. config/parts.yaml with the default
// cell's model base in $COSMOS_BENCH_MODEL_BASE).
inline const PartCatalog& bench_catalog() {
  static const PartCatalog catalog = [] {
    const char* from_environment = std::getenv("COSMOS_BENCH_CATALOG");
    return read_part_catalog(from_environment != nullptr && *from_environment != '\0'
                                 ? std::filesystem::path(from_environment)
                                 : std::filesystem::path(COSMOS_SOURCE_DIR) /
                                       "config/parts-regression.yaml");
  }();
  return catalog;
}

inline SimulatedSourceSettings source_settings(int parts) {
  SimulatedSourceSettings settings;
  settings.parts = parts;
  settings.seed = kSeed;
  return settings;
}

// A whole simulated stream in memory, so that the timed loops run no ray casting.
struct SimStream {
  std::vector<Profile> profiles;
  std::string error;  // why there is no stream (e.g. catalog meshes missing)
};

inline const SimStream& sim_stream(int points_per_profile) {
  static std::map<int, SimStream> streams;
  const auto [entry, inserted] = streams.try_emplace(points_per_profile);
  SimStream& stream = entry->second;
  if (!inserted) return stream;
  try {
    ScannerParameters parameters;
    parameters.points_per_profile = points_per_profile;
    SimulatedSource source(bench_catalog(), parameters, source_settings(kStreamParts));
    if (source.start() != SourceStatus::kOk) {
      stream.error = std::string(source.last_error());
      return stream;
    }
    Profile profile;
    source.reserve(profile);
    while (source.next(profile) == SourceStatus::kOk) stream.profiles.push_back(profile);
    if (stream.profiles.empty()) stream.error = "the simulated source gave no profiles";
  } catch (const std::exception& e) {
    stream.error = std::string(e.what()) + " (catalog meshes: scripts/fetch_catalog.sh)";
  }
  return stream;
}

// The value `fraction` of the way up the sorted values (0.5: the median).
inline double quantile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0;
  const auto at =
      values.begin() + static_cast<std::ptrdiff_t>(std::min(
                           values.size() - 1, static_cast<std::size_t>(fraction * values.size())));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

inline double median(std::vector<double> values) { return quantile(std::move(values), 0.5); }

}  // namespace cosmos::bench
