#pragma once
// Plain project structs <-> generated LCM message types. This is the one place where units
// change: the pipeline's millimetres become the robot's metres (position_m) and back, and the
// rotation becomes a unit quaternion with w >= 0 so that one rotation has one encoding.
#include <cosmos_lcm/cell_status_t.hpp>
#include <cosmos_lcm/part_pose_t.hpp>
#include <cosmos_lcm/range_profile_t.hpp>
#include <cstddef>

#include "core/profile.hpp"
#include "realtime/cell/cell_status.hpp"
#include "realtime/cell/part_pose.hpp"

namespace cosmos {

inline constexpr double kMillimetresPerMetre = 1000.0;

// The `message` arguments are overwritten field by field; their strings and arrays keep
// their capacity, so a publisher that reuses one message per type stops allocating.
void to_message(const PartPose& pose, cosmos_lcm::part_pose_t& message);
void to_message(const CellStatus& status, cosmos_lcm::cell_status_t& message);
void to_message(const Profile& profile, cosmos_lcm::range_profile_t& message);

// Inverses of the above (up to the metre -> millimetre rounding of the translation and the
// normalization of the quaternion). Enum values that are none of the known constants are
// kept as they are: to_string() then names them UNKNOWN.
void from_message(const cosmos_lcm::part_pose_t& message, PartPose& pose);
void from_message(const cosmos_lcm::cell_status_t& message, CellStatus& status);
// The widest profile any scanner config gives (scanner.points_per_profile is at most 8192):
// the bound for a reader that has no config (`cosmos listen`).
inline constexpr std::size_t kMaxProfileWidth = 8192;
// Sample spacings a scanner can have (a 10..5000 mm field of view over 16..8192 points), with
// a margin of ten either way: anything else is a damaged message, and the conditioner
// divides by it.
inline constexpr double kMinProfileSpacingMm = 1e-4;
inline constexpr double kMaxProfileSpacingMm = 3e3;
// Sample 0 within a kilometre of the scanner.
inline constexpr double kMaxProfileOriginMm = 1e6;

// Returns false (profile untouched) when width is negative or longer than the z_mm array, or
// x0_mm / dx_mm are outside the bounds above (NaN included).
bool from_message(const cosmos_lcm::range_profile_t& message, Profile& profile);

}  // namespace cosmos
