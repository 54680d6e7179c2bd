#pragma once
// One published pose as JSON for the web view (/api/poses, the page's table): the fields of
// part_pose_t in the cell's units (mm, and the rotation both as the quaternion the robot gets
// and as rotation_deg [rx, ry, rz] with R = Rz Ry Rx, the config's T_cell_scanner convention),
// plus the source's profile span of the part.
#include <cstdint>
#include <nlohmann/json.hpp>

#include "realtime/cell/part_pose.hpp"

namespace cosmos {

nlohmann::ordered_json pose_json(const PartPose& pose, std::int64_t first_profile,
                                 std::int64_t last_profile);

}  // namespace cosmos
