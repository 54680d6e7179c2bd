#pragma once
// COSMOS_STATUS as JSON for the web view (/api/status, the page's counters): one function over
// CellStatus's fields, one line each, in their declaration order, so a new counter in
// realtime/cell/cell_status.hpp needs one line here and the page lists it unasked.
#include <nlohmann/json.hpp>

#include "realtime/cell/cell_status.hpp"

namespace cosmos {

nlohmann::ordered_json status_json(const CellStatus& status);

}  // namespace cosmos
