#pragma once
// The model base a cell runs with: the file the config names, or one built on first run and
// cached beside the mesh cache (~/.cache/cosmos-cell/modelbases/), named after the hash of the
// catalog's content and every parameter the base depends on, so a changed catalog, scanner or
// belt threshold builds a new base instead of loading a stale one.
#include <filesystem>

#include "core/cosmos_parameters.hpp"
#include "core/modelbase/model_base.hpp"
#include "realtime/config/cell_config.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos {

std::filesystem::path cached_model_base_path(const CellConfig& config, const PartCatalog& catalog);

// A loaded base and the COSMOS parameters it was built with, which the cell's every analysis
// of a scan uses (the recognizer, the scan loop's incremental COSMOS, the part views).
struct CellModelBase {
  ModelBase base;
  CosmosParameters cosmos;
};

// Loads the configured or cached base; builds and caches it (with a progress bar) when the
// cache has none. InputError naming the file when a configured base is missing or refused:
// a base whose views were taken on another grid (either pitch) or belt threshold than the
// cell's conditioning gives its scans.
CellModelBase load_cell_model_base(const CellConfig& config, const PartCatalog& catalog);

}  // namespace cosmos
