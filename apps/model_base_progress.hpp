#pragma once
// The progress of a model-base build on stderr (`cosmos modelbase build`, and `cosmos cell`
// building its base on first run): a bar redrawn in place on a terminal; in a log, one line per
// finished part.
#include "sim/model_base_build/model_base_builder.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos {

ModelBaseProgress progress_printer(const PartCatalog& catalog);

}  // namespace cosmos
