#pragma once
// Where the simulated conveyor puts its parts on the belt: one after another along the belt
// (y), part_gap_mm of belt between bounding boxes or a seeded gap in [part_gap_mm,
// part_gap_max_mm], 0 for parts touching end to end, or in groups of group_size touching end
// to end, part_gap_mm between groups; or in pairs side by side across the belt
// (x), across_gap_mm apart (0: touching), each pair part_gap_mm behind the previous one. Each
// part's across-belt offset is seeded when random_x_offset asks for one (a pair's, as one).
//
// Belt frame as in simulated_conveyor.hpp: part 0 meets the laser sheet first, so the parts
// lie at decreasing y; the first one's downstream end is a lead-in of belt away from y = 0.
#include <Eigen/Core>
#include <vector>

#include "realtime/config/sim_source_settings.hpp"

namespace cosmos {

// Empty belt before the first part and after the last, mm: at least part_gap_mm, and never
// less than this, so that a stream of touching parts still starts and ends on empty belt.
inline constexpr double kMinLeadInMm = 10.0;

struct PartPlacement {
  double x_mm = 0;  // centre of the part's bounding box across the belt
  double y_mm = 0;  // and along it
};

// `box_sizes_mm`: each part's bounding box in its belt orientation, in sequence order.
// `half_field_mm`: half the field of view at belt height.
std::vector<PartPlacement> lay_out_parts(const std::vector<Eigen::Vector3d>& box_sizes_mm,
                                         const SimulatedConveyorSettings& settings,
                                         double half_field_mm);

// The lead-in (and trailing belt) of a layout, mm.
double lead_in_mm(const SimulatedConveyorSettings& settings);

}  // namespace cosmos
