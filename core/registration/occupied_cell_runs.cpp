#include "core/registration/occupied_cell_runs.hpp"

namespace cosmos {

std::vector<std::uint8_t> encode_occupied_cell_runs(const std::vector<std::int32_t>& cell_point) {
  return encode_occupied_cell_runs(cell_point.size(),
                                   [&](std::size_t cell) { return cell_point[cell] >= 0; });
}

}  // namespace cosmos
