#include "realtime/loop/scan_loop.hpp"

#include <algorithm>
#include <thread>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos {

PartBuilder::PartBuilder(const CosmosParameters& cosmos_parameters, int width, int max_rows,
                         double grid_mm)
    : cosmos(cosmos_parameters, width, max_rows, grid_mm, grid_mm),
      labels(static_cast<std::size_t>(width) * static_cast<std::size_t>(max_rows), -1) {}

bool PartBuilder::owns(std::int64_t id) const {
  if (id == part_id) return true;
  for (int k = 0; k < merged_count; ++k)
    if (merged_ids[static_cast<std::size_t>(k)] == id) return true;
  return false;
}

namespace {

PartTrackerParameters tracking_with_shadows(const ScanLoopSettings& settings) {
  PartTrackerParameters tracking = settings.tracking;
  if (tracking.shadow_rows_per_mm == 0 && settings.conditioning.grid_mm > 0)
    tracking.shadow_rows_per_mm = settings.shadow_length_per_height / settings.conditioning.grid_mm;
  return tracking;
}

}  // namespace

ScanLoop::ScanLoop(const ScanLoopSettings& settings)
    : settings_(settings),
      conditioner_(settings.conditioning, settings.cosmos.fit),
      tracker_(tracking_with_shadows(settings), conditioner_.width()),
      completed_(static_cast<std::size_t>(std::max(settings.parts.part_queue_slots, 1))),
      returned_(static_cast<std::size_t>(std::max(settings.parts.builders, 1))),
      lost_(static_cast<std::size_t>(PartQueueSettings::kLostPartSlots)),
      row_stamps_(static_cast<std::size_t>(std::max(settings.tracking.link_gap_rows, 0) + 3)),
      row_belt_(static_cast<std::size_t>(conditioner_.width())),
      row_loop_(static_cast<std::size_t>(conditioner_.width())),
      belt_seen_(static_cast<std::size_t>(conditioner_.width()), 0) {
  for (int b = 0; b < std::max(settings.parts.builders, 1); ++b) {
    builders_.push_back(std::make_unique<PartBuilder>(settings.cosmos, conditioner_.width(),
                                                      settings.max_part_rows,
                                                      settings.conditioning.grid_mm));
    free_builders_.push_back(b);
  }
  open_builders_.reserve(builders_.size());
  unbuilt_.reserve(static_cast<std::size_t>(std::max(settings.tracking.max_open_parts, 1)));
}

ScanLoop::RowStamp& ScanLoop::stamp_of_row(std::int64_t row) {
  return row_stamps_[static_cast<std::size_t>(row % static_cast<std::int64_t>(row_stamps_.size()))];
}

void ScanLoop::report_lost(const LostPart& lost) {
  counters_.parts_dropped.fetch_add(1, std::memory_order_relaxed);
  if (!lost_.try_push(lost)) counters_.lost_unreported.fetch_add(1, std::memory_order_relaxed);
}

double ScanLoop::x0_loop_mm() const {
  return -(settings_.conditioning.x_min_mm + (width() - 1) * settings_.conditioning.grid_mm);
}

void ScanLoop::reclaim_returned() {
  int index = -1;
  while (returned_.try_pop(index)) free_builders_.push_back(index);
}

int ScanLoop::acquire_builder() {
  reclaim_returned();
  // Wait only for builders the recognizer holds: those of open parts come back only when
  // their parts complete, which needs this very loop to go on.
  const auto at_recognizer = [this] {
    return builders_.size() - free_builders_.size() - open_builders_.size();
  };
  while (free_builders_.empty() && settings_.wait_for_recognizer && at_recognizer() > 0) {
    std::this_thread::yield();
    reclaim_returned();
  }
  if (free_builders_.empty()) return -1;
  const int index = free_builders_.back();
  free_builders_.pop_back();
  return index;
}

int ScanLoop::builder_of(std::int64_t id) const {
  for (int index : open_builders_)
    if (builders_[static_cast<std::size_t>(index)]->part_id == id) return index;
  return -1;
}

void ScanLoop::complete(const TrackedPart& part) {
  const int index = builder_of(part.id);
  if (part.merged_into >= 0) {
    const int kept = builder_of(part.merged_into);
    if (kept >= 0) {
      PartBuilder& into = *builders_[static_cast<std::size_t>(kept)];
      const PartBuilder* from =
          index >= 0 ? builders_[static_cast<std::size_t>(index)].get() : nullptr;
      const auto add = [&into](std::int64_t id) {
        if (into.merged_count < kMaxMergedIds)
          into.merged_ids[static_cast<std::size_t>(into.merged_count++)] = id;
      };
      add(part.id);
      for (int k = 0; from && k < from->merged_count; ++k)
        add(from->merged_ids[static_cast<std::size_t>(k)]);
    }
  }
  if (index < 0) {
    // Started without a builder: reported now that its extent is known, unless it was noise
    // or joined a part whose builder holds the rest of it (that blob's poses cover it).
    const auto unbuilt = std::find_if(unbuilt_.begin(), unbuilt_.end(),
                                      [&part](const UnbuiltPart& u) { return u.id == part.id; });
    if (unbuilt == unbuilt_.end()) return;
    const RowStamp first = unbuilt->first;
    unbuilt_.erase(unbuilt);
    if (part.noise) {
      counters_.noise_components.fetch_add(1, std::memory_order_relaxed);
      return;
    }
    if (part.merged_into >= 0) {
      // Joined another part: an unbuilt one inherits this one's start; a built one covers it.
      for (UnbuiltPart& into : unbuilt_)
        if (into.id == part.merged_into && first.profile < into.first.profile) into.first = first;
      return;
    }
    const RowStamp& last = stamp_of_row(part.last_row);
    report_lost({LostPartReason::kNoBuilder, first.profile, last.profile, first.encoder_ticks,
                 last.encoder_ticks, last.t_us, width() - 1 - part.column_max,
                 width() - 1 - part.column_min, part.max_z_mm});
    return;
  }
  open_builders_.erase(std::find(open_builders_.begin(), open_builders_.end(), index));
  if (part.merged_into >= 0 || part.noise) {
    counters_.noise_components.fetch_add(part.noise ? 1 : 0, std::memory_order_relaxed);
    free_builders_.push_back(index);
    return;
  }
  PartBuilder& builder = *builders_[static_cast<std::size_t>(index)];
  builder.column_min = width() - 1 - part.column_max;
  builder.column_max = width() - 1 - part.column_min;
  builder.max_z_mm = part.max_z_mm;
  builder.soft_link_of = part.soft_link_of;
  builder.has_soft_successor = part.has_soft_successor;
  builder.tracked_rows = part.last_row - part.first_row + 1;
  builder.completed_ns = monotonic_now_ns();
  counters_.parts_seen.fetch_add(1, std::memory_order_relaxed);
  counters_.parts_truncated.fetch_add(builder.truncated ? 1 : 0, std::memory_order_relaxed);
  while (!completed_.try_push(index)) {
    if (!settings_.wait_for_recognizer) {
      report_lost({LostPartReason::kQueueFull, builder.first_profile,
                   builder.first_profile + builder.cosmos.rows() - 1, builder.first_encoder_ticks,
                   builder.last_encoder_ticks, builder.last_t_us, builder.column_min,
                   builder.column_max, part.max_z_mm});
      free_builders_.push_back(index);
      return;
    }
    std::this_thread::yield();
  }
}

void ScanLoop::start_parts(std::int64_t profile_index, const Profile& profile) {
  for (const TrackedPart& part : tracker_.open_parts()) {
    if (part.first_row != row_index_ || builder_of(part.id) >= 0) continue;
    const int index = acquire_builder();
    if (index < 0) {
      // Reported when the tracker completes it (complete()); the tracker never holds more
      // open parts than unbuilt_ has room for.
      if (unbuilt_.size() < unbuilt_.capacity())
        unbuilt_.push_back({part.id, {profile_index, profile.encoder_ticks, profile.t_us}});
      else
        counters_.parts_dropped.fetch_add(1, std::memory_order_relaxed);
      continue;
    }
    PartBuilder& builder = *builders_[static_cast<std::size_t>(index)];
    builder.cosmos.begin_part(x0_loop_mm(),
                              static_cast<double>(profile_index) * settings_.conditioning.grid_mm);
    // No clearing of labels: every row the part gets is written whole (process), and only
    // those are read; filling the whole width x max_rows buffer here would make a part's
    // first profile the loop's slowest.
    builder.part_id = part.id;
    builder.merged_count = 0;
    builder.first_profile = profile_index;
    builder.first_encoder_ticks = profile.encoder_ticks;
    builder.truncated = false;
    builder.last_encoder_ticks = profile.encoder_ticks;
    builder.last_t_us = profile.t_us;
    open_builders_.push_back(index);
  }
}

void ScanLoop::process(const Profile& profile) {
  const auto profile_index = static_cast<std::int64_t>(profile.seq);
  // A refused profile becomes an empty row, which keeps the rows in step with the profiles
  // (a part's length and encoder range stay right); the refusal is counted for the operator.
  if (!conditioner_.condition(profile, row_belt_.data(), belt_seen_.data()))
    counters_.profiles_refused.fetch_add(1, std::memory_order_relaxed);
  std::reverse_copy(row_belt_.begin(), row_belt_.end(), row_loop_.begin());
  stamp_of_row(row_index_) = {profile_index, profile.encoder_ticks, profile.t_us};
  for (const TrackedPart& part : tracker_.add_row(row_belt_.data(), row_index_, belt_seen_.data()))
    complete(part);
  counters_.runs_dropped.store(tracker_.dropped_runs(), std::memory_order_relaxed);
  start_parts(profile_index, profile);
  const std::vector<std::int64_t>& labels = tracker_.row_labels();
  const int w = width();
  for (int index : open_builders_) {
    PartBuilder& builder = *builders_[static_cast<std::size_t>(index)];
    const int row = builder.cosmos.rows();
    if (!builder.cosmos.add_row(row_loop_.data())) {
      builder.truncated = true;
      continue;
    }
    std::int64_t* out = builder.labels.data() + static_cast<std::size_t>(row) * w;
    for (int c = 0; c < w; ++c) out[c] = labels[static_cast<std::size_t>(w - 1 - c)];
    builder.last_encoder_ticks = profile.encoder_ticks;
    builder.last_t_us = profile.t_us;
  }
  ++row_index_;
  counters_.profiles.fetch_add(1, std::memory_order_relaxed);
}

void ScanLoop::flush() {
  // Empty rows until every open part has been idle long enough to complete: a stream that
  // ends right behind a part must not lose it. Their stamps are the last profile's.
  std::fill(row_belt_.begin(), row_belt_.end(), Profile::kNoData);
  const RowStamp last = row_index_ > 0 ? stamp_of_row(row_index_ - 1) : RowStamp{};
  for (int k = 0; k <= settings_.tracking.link_gap_rows + 1 && !tracker_.open_parts().empty();
       ++k) {
    stamp_of_row(row_index_) = last;
    for (const TrackedPart& part : tracker_.add_row(row_belt_.data(), row_index_)) complete(part);
    ++row_index_;
  }
}

}  // namespace cosmos
