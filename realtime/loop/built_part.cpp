#include "realtime/loop/built_part.hpp"

namespace cosmos {

bool owns_tracker_id(std::int64_t part_id,
                     const std::array<std::int64_t, kMaxMergedIds>& merged_ids, int merged_count,
                     std::int64_t id) {
  if (id == part_id) return true;
  for (int k = 0; k < merged_count; ++k)
    if (merged_ids[static_cast<std::size_t>(k)] == id) return true;
  return false;
}

bool BuiltPart::owns(std::int64_t id) const {
  return owns_tracker_id(part_id, merged_ids, merged_count, id);
}

bool BuiltPart::same_as(const BuiltPart& other) const {
  return cosmos == other.cosmos && rows == other.rows && part_id == other.part_id &&
         merged_count == other.merged_count && merged_ids == other.merged_ids &&
         first_profile == other.first_profile && last_data_profile == other.last_data_profile &&
         first_encoder_ticks == other.first_encoder_ticks &&
         last_data_encoder_ticks == other.last_data_encoder_ticks &&
         last_data_t_us == other.last_data_t_us && column_min == other.column_min &&
         column_max == other.column_max && max_z_mm == other.max_z_mm &&
         tracked_rows == other.tracked_rows && truncated == other.truncated;
}

}  // namespace cosmos
