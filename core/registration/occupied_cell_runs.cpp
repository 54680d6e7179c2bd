#include "core/registration/occupied_cell_runs.hpp"

namespace cosmos {

std::vector<std::uint8_t> encode_occupied_cell_runs(const std::vector<std::int32_t>& cell_point) {
  BitWriter runs;
  std::size_t run = 0;
  bool occupied = false;
  for (std::int32_t point : cell_point) {
    if ((point >= 0) != occupied) {
      runs.put_gamma(static_cast<std::uint32_t>(run + 1));
      occupied = !occupied;
      run = 0;
    }
    ++run;
  }
  if (!cell_point.empty()) runs.put_gamma(static_cast<std::uint32_t>(run + 1));
  return runs.finish();
}

}  // namespace cosmos
