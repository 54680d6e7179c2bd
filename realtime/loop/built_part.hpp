#pragma once
// What recognition reads of a part's builder: its rows up to its last row with data, the
// tracker's ids and extent of the part, and the stamps its pose holds at. A copy, so that a
// recognizer worker can read it while the acquisition thread goes on with the builder: the
// rows it names are final (their COSMOS is done and never written again, PartRows keeps each
// row where it was put) and later rows go to other places of the pool. That is how a part is
// recognized in the rows after its end, before the tracker has completed it (speculative
// recognition, realtime/cell/recognizer_thread.cpp).
#include <array>
#include <cstdint>

#include "realtime/loop/incremental_cosmos.hpp"

namespace cosmos {

inline constexpr int kMaxMergedIds = 16;

// Whether tracker id `id` is a part's own (`part_id`) or one of the `merged_count` ids merged
// into it.
bool owns_tracker_id(std::int64_t part_id,
                     const std::array<std::int64_t, kMaxMergedIds>& merged_ids, int merged_count,
                     std::int64_t id);

struct BuiltPart {
  const IncrementalCosmos* cosmos = nullptr;
  int rows = 0;  // rows [0, rows) of *cosmos: up to its last row with data
  std::int64_t part_id = -1;
  std::array<std::int64_t, kMaxMergedIds> merged_ids{};  // ids merged into this part
  int merged_count = 0;
  std::int64_t first_profile = 0;  // the source's profile index of row 0
  std::int64_t last_data_profile = 0;
  // The encoder counts and exposure time of its first row and of its last row with data,
  // where its pose holds.
  std::int64_t first_encoder_ticks = 0;
  std::int64_t last_data_encoder_ticks = 0;
  std::int64_t last_data_t_us = 0;
  int column_min = 0;  // the tracked part's extent, loop-frame columns
  int column_max = 0;
  float max_z_mm = 0;             // the tracked part's highest sample
  std::int64_t tracked_rows = 0;  // rows from its first to its last data (all, when truncated)
  bool truncated = false;         // longer than the builder's rows: rows dropped

  bool owns(std::int64_t id) const;
  // The same part over the same rows: what a recognition of either gives holds for both.
  bool same_as(const BuiltPart& other) const;
};

}  // namespace cosmos
