// `cosmos modelbase build` and `cosmos modelbase info`: the model base of ch. 4 (every catalog
// part from the §4.5 view directions, grouped per part into view clusters, Fig. 5.3) built
// into one file (core/io/model_base_file.hpp), and a summary of such a file.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <type_traits>

#include "apps/command_registry.hpp"
#include "apps/model_base_progress.hpp"
#include "core/input_error.hpp"
#include "core/io/model_base_file.hpp"
#include "core/parameter_range_check.hpp"
#include "realtime/config/cell_config.hpp"
#include "sim/model_base_build/model_base_builder.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos::cli {
namespace {

namespace fs = std::filesystem;

// Numbers arrive as text so that a bad one is reported in one line naming the option.
struct BuildOptions {
  std::string catalog;
  std::string views = "320";
  std::string threads;
  std::string config;
  std::string cluster_level;
  std::string clusters;
  std::string out;
};

[[noreturn]] void fail(const std::string& command, const std::string& reason) {
  throw InputError("modelbase " + command + ": " + reason);
}

template <class Number>
Number parse_number(const char* option, const std::string& text, const char* expected) {
  Number value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end)
    fail("build", std::string(option) + " '" + text + "': expected " + expected);
  if constexpr (std::is_floating_point_v<Number>) {
    if (!std::isfinite(value))
      fail("build", std::string(option) + " '" + text + "': must be finite");
  }
  return value;
}

ModelBaseBuildSettings build_settings(const BuildOptions& options) {
  ModelBaseBuildSettings settings;
  settings.view_count = parse_number<int>("--views", options.views, "an integer in [1, 320]");
  if (settings.view_count < 1 || settings.view_count > kFullViewCount)
    fail("build", "--views '" + options.views + "': expected an integer in [1, 320]");
  if (!options.threads.empty()) {
    settings.threads = parse_number<int>("--threads", options.threads, "a positive integer");
    // Each std::thread reserves its stack: a billion of them end in std::system_error.
    if (settings.threads < 1 || settings.threads > 1024)
      fail("build", "--threads '" + options.threads + "': expected an integer in [1, 1024]");
  }
  if (!options.cluster_level.empty() && !options.clusters.empty())
    fail("build", "give either --cluster-level or --clusters, not both");
  if (!options.cluster_level.empty()) {
    settings.grouping.cut_level =
        parse_number<double>("--cluster-level", options.cluster_level, "a number > 0");
    if (!(settings.grouping.cut_level > 0))
      fail("build", "--cluster-level '" + options.cluster_level + "': must be > 0");
  }
  if (!options.clusters.empty()) {
    settings.grouping.cluster_count =
        parse_number<int>("--clusters", options.clusters, "a positive integer");
    if (settings.grouping.cluster_count < 1)
      fail("build", "--clusters '" + options.clusters + "': expected a positive integer");
  }
  // The options override the grouping parameters: held to their declared ranges.
  if (const auto problem = first_out_of_range(settings.grouping, "grouping"))
    fail("build", (options.clusters.empty() ? "--cluster-level: " : "--clusters: ") + *problem);
  return settings;
}

void run_build(const BuildOptions& options) {
  if (options.out.empty()) fail("build", "missing --out FILE");
  const fs::path out = options.out;
  const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code error;
  if (!fs::is_directory(parent, error))
    fail("build", out.string() + ": no directory " + parent.string());
  ModelBaseBuildSettings settings = build_settings(options);
  // The cell config's scanner and conditioning (whose belt threshold the views are cut at).
  const CellConfig config =
      options.config.empty() ? CellConfig{} : load_cell_config(options.config);
  const ScannerParameters& scanner = config.scanner;
  settings.conditioning = config.conditioning;
  const PartCatalog catalog = read_part_catalog(find_part_catalog(options.catalog));

  const auto start = std::chrono::steady_clock::now();
  const ModelBase base = build_model_base(catalog, scanner, settings, progress_printer(catalog));
  write_model_base(base, out);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t scanned = catalog.parts.size() * static_cast<std::size_t>(settings.view_count);
  std::printf(
      "modelbase build: %zu parts, %zu views (%zu measured nothing), %zu clusters -> %s (%ju "
      "bytes) in %.0f s\n",
      base.parts.size(), base.views.size(), scanned - base.views.size(), base.clusters.size(),
      out.string().c_str(), static_cast<std::uintmax_t>(fs::file_size(out)), seconds);
}

void run_info(const std::string& file) {
  if (file.empty()) fail("info", "missing FILE");
  const ModelBase base = read_model_base(file);
  std::printf("model base: %s\nfile size: %ju bytes\nformat version: %u\ncatalog hash: %s\n",
              file.c_str(), static_cast<std::uintmax_t>(fs::file_size(file)),
              ModelBase::kFormatVersion, base.catalog_hash.c_str());
  std::printf("parts: %zu, views: %zu, clusters: %zu\n", base.parts.size(), base.views.size(),
              base.clusters.size());
  std::printf("%-20s %6s %9s %15s %8s %12s %9s %13s %s\n", "part", "views", "clusters",
              "control_points", "size_mm", "diameter_mm", "symmetric", "resting_poses",
              "resting_coverage");
  for (std::size_t p = 0; p < base.parts.size(); ++p) {
    std::size_t views = 0, clusters = 0, points = 0;
    for (const ModelBaseView& view : base.views) {
      if (view.part_index != static_cast<int>(p)) continue;
      ++views;
      points += static_cast<std::size_t>(view.registration_packed.size());
    }
    for (const ViewCluster& cluster : base.clusters)
      clusters += cluster.part_index == static_cast<int>(p);
    const ModelPart& part = base.parts[p];
    std::printf("%-20s %6zu %9zu %15zu %8g %12.2f %9s %13zu %.3f\n", part.name.c_str(), views,
                clusters, points, part.size_mm, part.diameter_mm, part.symmetric ? "yes" : "no",
                part.resting_poses.size(), part.resting_coverage());
  }
  std::printf("parameters:\n%s", base.parameters_text.c_str());
}

void install(CLI::App& root) {
  CLI::App* modelbase = root.add_subcommand(
      "modelbase", "The model base: catalog parts' views, COSMOS and view clusters");
  modelbase->require_subcommand(1);

  auto build_options = std::make_shared<BuildOptions>();
  CLI::App* build = modelbase->add_subcommand(
      "build", "Scan every catalog part from the view sphere into a model-base file");
  build
      ->add_option("--catalog", build_options->catalog,
                   "part catalog YAML (default: config/parts.yaml)")
      ->type_name("FILE");
  build
      ->add_option("--views", build_options->views,
                   "view directions per part: 320 (twice-subdivided icosahedron), or the first N "
                   "of a spread "
                   "order (20: face centres, 80: once subdivided)")
      ->type_name("N")
      ->capture_default_str();
  build->add_option("--threads", build_options->threads, "worker threads (default: every core)")
      ->type_name("N");
  build
      ->add_option("--config", build_options->config,
                   "cell config whose scanner: and conditioning: sections override the defaults")
      ->type_name("FILE");
  char level_help[96];
  std::snprintf(level_help, sizeof level_help,
                "cut each part's dendrogram at this Eq. 4.3 dissimilarity (default %g)",
                kDefaultViewCutLevel);
  build->add_option("--cluster-level", build_options->cluster_level, level_help)->type_name("D");
  build
      ->add_option("--clusters", build_options->clusters,
                   "cut each part's dendrogram into K clusters instead")
      ->type_name("K");
  build->add_option("--out", build_options->out, "output model-base file")->type_name("FILE");
  build->callback([build_options] { run_build(*build_options); });

  auto info_file = std::make_shared<std::string>();
  CLI::App* info = modelbase->add_subcommand(
      "info", "Parts, views, clusters per part, parameters and size of a model base");
  info->add_option("FILE", *info_file, "model-base file")->type_name("FILE");
  info->callback([info_file] { run_info(*info_file); });
}

const CommandRegistration registration("modelbase", install);

}  // namespace
}  // namespace cosmos::cli
