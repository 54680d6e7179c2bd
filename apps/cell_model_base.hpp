#pragma once
// A model base as a cell runs with it: the base and the COSMOS parameters it was built with,
// which the cell's every analysis of a scan uses (the recognizer, the scan loop's incremental
// COSMOS, the part views).
#include <filesystem>

#include "core/cosmos_parameters.hpp"
#include "core/modelbase/model_base.hpp"
#include "realtime/config/cell_config.hpp"

namespace cosmos {

struct CellModelBase {
  ModelBase base;
  CosmosParameters cosmos;
};

// Reads `path` for a cell with `config`. InputError naming the file when it is missing or
// refused: a base whose views were taken on another grid (either pitch) or belt threshold
// than the cell's conditioning gives its scans. A base it accepts is named on stderr in one line
// (parts, views, when the file was written), so the reuse of a cached base is not silent.
// With faults.corrupt_model_base the base is read with one byte flipped, and refused so (the
// injected fault of a damaged base at start).
CellModelBase read_cell_model_base(const std::filesystem::path& path, const CellConfig& config);

}  // namespace cosmos
