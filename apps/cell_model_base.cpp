#include "apps/cell_model_base.hpp"

#include <cstdio>

#include "apps/model_base_progress.hpp"
#include "core/input_error.hpp"
#include "core/io/model_base_file.hpp"
#include "core/io/xxh64.hpp"
#include "sim/model_base_build/catalog_content_hash.hpp"
#include "sim/model_base_build/model_base_builder.hpp"
#include "sim/model_base_build/model_base_parameters.hpp"

namespace cosmos {
namespace {

ModelBaseBuildSettings build_settings(const CellConfig& config) {
  ModelBaseBuildSettings settings;
  settings.view_count = config.cell.model_views;
  settings.conditioning = config.conditioning;
  return settings;
}

CellModelBase read_for_cell(const std::filesystem::path& path, const CellConfig& config) {
  CellModelBase loaded{read_model_base(path), {}};
  if (const auto difference = conditioning_difference(
          model_base_view_conditioning(loaded.base, path), config.conditioning)) {
    throw InputError(path.string() + ": its views were taken with other conditioning: " +
                     difference->key + " is " + difference->actual + ", " + config.file.string() +
                     " gives " + difference->expected);
  }
  loaded.cosmos = model_base_cosmos_parameters(loaded.base, path);
  return loaded;
}

}  // namespace

std::filesystem::path cached_model_base_path(const CellConfig& config, const PartCatalog& catalog) {
  const ModelBaseBuildSettings settings = build_settings(config);
  const std::string key =
      catalog_content_hash(catalog) + model_base_parameters_text(config.scanner, settings);
  char name[64];
  std::snprintf(name, sizeof name, "cell-%d-views-%016llx.cmb", settings.view_count,
                static_cast<unsigned long long>(xxh64(key)));
  return default_mesh_cache_dir().parent_path() / "modelbases" / name;
}

CellModelBase load_cell_model_base(const CellConfig& config, const PartCatalog& catalog) {
  if (!config.cell.model_base.empty()) return read_for_cell(config.cell.model_base, config);
  const std::filesystem::path path = cached_model_base_path(config, catalog);
  if (std::filesystem::exists(path)) return read_for_cell(path, config);
  std::fprintf(stderr, "cell: building the model base (first run; cached as %s)\n",
               path.string().c_str());
  std::error_code error;
  std::filesystem::create_directories(path.parent_path(), error);
  if (error)
    throw InputError(path.parent_path().string() + ": cannot create (" + error.message() + ")");
  const ModelBase base =
      build_model_base(catalog, config.scanner, build_settings(config), progress_printer(catalog));
  write_model_base(base, path);
  return read_for_cell(path, config);
}

}  // namespace cosmos
