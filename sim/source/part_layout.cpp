#include "sim/source/part_layout.hpp"

#include <algorithm>

#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

// Independent random streams from the one settings seed (the offsets' stream is the one the
// conveyor has always used, so single-file layouts keep their placements).
constexpr std::uint64_t kOffsetStream = 0x0FF5E7;
constexpr std::uint64_t kGapStream = 0x6A9;
// Boxes placed exactly edge to edge may overlap by a rounding error, which the scene refuses
// (ConveyorScene::add_part): touching parts are this far apart.
constexpr double kTouchingSlackMm = 1e-3;

// A seeded offset in [-reach, reach] for slot i.
double seeded_offset(const SimulatedConveyorSettings& settings, std::size_t i, double reach_mm) {
  if (!settings.random_x_offset) return 0.0;
  SeededRandom offset(mix_seed(mix_seed(settings.seed, kOffsetStream), i));
  return std::max(0.0, reach_mm) * (2.0 * offset.uniform() - 1.0);
}

double seeded_gap(const SimulatedConveyorSettings& settings, std::size_t i) {
  if (settings.part_gap_max_mm <= settings.part_gap_mm)
    return std::max(settings.part_gap_mm, kTouchingSlackMm);
  SeededRandom gap(mix_seed(mix_seed(settings.seed, kGapStream), i));
  return std::max(
      kTouchingSlackMm,
      settings.part_gap_mm + (settings.part_gap_max_mm - settings.part_gap_mm) * gap.uniform());
}

}  // namespace

double lead_in_mm(const SimulatedConveyorSettings& settings) {
  return std::max(settings.part_gap_mm, kMinLeadInMm);
}

std::vector<PartPlacement> lay_out_parts(const std::vector<Eigen::Vector3d>& box_sizes_mm,
                                         const SimulatedConveyorSettings& settings,
                                         double half_field_mm) {
  std::vector<PartPlacement> placements(box_sizes_mm.size());
  const double margin_mm = settings.edge_margin_mm;
  // The downstream (+y) end of the next slot.
  double next_y_max_mm = -lead_in_mm(settings);
  const double across_gap_mm = std::max(settings.across_gap_mm, kTouchingSlackMm);
  const std::size_t per_slot = settings.side_by_side ? 2 : 1;
  for (std::size_t first = 0, slot = 0; first < box_sizes_mm.size(); first += per_slot, ++slot) {
    const std::size_t last = std::min(first + per_slot, box_sizes_mm.size()) - 1;
    double width_mm = 0, length_mm = 0;
    for (std::size_t i = first; i <= last; ++i) {
      width_mm += box_sizes_mm[i].x();
      length_mm = std::max(length_mm, box_sizes_mm[i].y());
    }
    if (last > first) width_mm += across_gap_mm;
    const double centre_mm =
        seeded_offset(settings, slot, half_field_mm - 0.5 * width_mm - margin_mm);
    double x_min_mm = centre_mm - 0.5 * width_mm;
    for (std::size_t i = first; i <= last; ++i) {
      // The pair's downstream ends level, each part centred in its share of the width.
      placements[i].x_mm = x_min_mm + 0.5 * box_sizes_mm[i].x();
      placements[i].y_mm = next_y_max_mm - 0.5 * box_sizes_mm[i].y();
      x_min_mm += box_sizes_mm[i].x() + across_gap_mm;
    }
    const bool in_group = !settings.side_by_side && settings.group_size > 1 &&
                          (slot + 1) % static_cast<std::size_t>(settings.group_size) != 0;
    next_y_max_mm -= length_mm + (in_group ? kTouchingSlackMm : seeded_gap(settings, slot));
  }
  return placements;
}

}  // namespace cosmos
