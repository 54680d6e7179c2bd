#pragma once
// Which cells of a registration grid hold a control point (packed_registration_points.hpp),
// as the lengths of the alternating runs of empty and occupied cells in grid (row-major)
// order, the first run empty (possibly of length 0), each length + 1 in an Elias-gamma code:
// a view's points cover a few compact regions, a few runs per grid row.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/registration/rice_bit_stream.hpp"

namespace cosmos {

// `cells` cells in order, cell k occupied when occupied(k).
template <class IsOccupied>
std::vector<std::uint8_t> encode_occupied_cell_runs(std::size_t cells, IsOccupied&& occupied) {
  BitWriter runs;
  std::size_t run = 0;
  bool in_occupied_run = false;
  for (std::size_t cell = 0; cell < cells; ++cell) {
    if (occupied(cell) != in_occupied_run) {
      runs.put_gamma(static_cast<std::uint32_t>(run + 1));
      in_occupied_run = !in_occupied_run;
      run = 0;
    }
    ++run;
  }
  if (cells > 0) runs.put_gamma(static_cast<std::uint32_t>(run + 1));
  return runs.finish();
}

// `cell_point`: per cell its point index, -1 for none.
std::vector<std::uint8_t> encode_occupied_cell_runs(const std::vector<std::int32_t>& cell_point);

// Calls occupied_run(first_cell, end_cell) for each run of occupied cells, at most max_points
// cells in all. Returns whether the runs cover exactly `cells` cells, max_points of them
// occupied, with no code an encoder never writes and nothing after them; reads nothing outside
// `runs`.
template <class OccupiedRun>
bool visit_occupied_cell_runs(std::span<const std::uint8_t> runs, std::size_t cells,
                              std::size_t max_points, OccupiedRun&& occupied_run) {
  BitReader reader(runs);
  std::size_t cell = 0, points = 0;
  for (bool occupied = false; cell < cells; occupied = !occupied) {
    const std::uint32_t code = reader.get_gamma();
    if (code == 0 || code - 1 > cells - cell) return false;
    std::size_t end = cell + (code - 1);
    if (occupied) {
      const bool too_many = end - cell > max_points - points;
      if (too_many) end = cell + (max_points - points);
      occupied_run(cell, end);
      points += end - cell;
      if (too_many) return false;
    }
    cell = end;
  }
  // The last code ends in the last byte, zero padding after it: no run past the grid.
  const std::uint64_t stream_bits = 8 * static_cast<std::uint64_t>(runs.size());
  if (points != max_points || reader.position_bits() > stream_bits ||
      stream_bits - reader.position_bits() >= 8)
    return false;
  return reader.get(static_cast<int>(stream_bits - reader.position_bits())) == 0;
}

}  // namespace cosmos
