#pragma once
// COSMOS_STATUS as JSON for the web view (/api/status, the page's counters): the state, every
// total of CellStatus::visit_totals in its order, then the period's timings and the queues, so
// a new counter declared in realtime/cell/cell_status.hpp shows on the page unasked.
#include <nlohmann/json.hpp>

#include "realtime/cell/cell_status.hpp"

namespace cosmos {

nlohmann::ordered_json status_json(const CellStatus& status);

}  // namespace cosmos
