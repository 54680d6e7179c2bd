#include "realtime/loop/scan_loop.hpp"

#include <algorithm>
#include <limits>
#include <thread>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos {

const char* lost_part_reason_text(LostPartReason reason) {
  switch (reason) {
    case LostPartReason::kNoBuilder:
      return "dropped: no free part builder when it arrived (realtime.part_builders)";
    case LostPartReason::kQueueFull:
      return "dropped: the recognizer's queue was full (realtime.part_queue_slots)";
    case LostPartReason::kNoRowMemory:
      return "dropped: the part builders' row pool was used up (realtime.row_blocks)";
  }
  return "dropped";
}

PartBuilder::PartBuilder(const CosmosParameters& cosmos_parameters, int width, int max_rows,
                         double grid_mm, RowBlockPool& row_pool)
    : cosmos(cosmos_parameters, width, max_rows, grid_mm, grid_mm, row_pool) {}

BuiltPart PartBuilder::built() const {
  BuiltPart part;
  part.cosmos = &cosmos;
  part.rows = static_cast<int>(std::min<std::int64_t>(
      cosmos.rows(), std::max<std::int64_t>(0, last_data_row - first_row + 1)));
  part.part_id = part_id;
  part.merged_ids = merged_ids;
  part.merged_count = merged_count;
  part.first_profile = first_profile;
  part.last_data_profile = last_data_profile;
  part.first_encoder_ticks = first_encoder_ticks;
  part.last_data_encoder_ticks = last_data_encoder_ticks;
  part.last_data_t_us = last_data_t_us;
  part.column_min = column_min;
  part.column_max = column_max;
  part.max_z_mm = max_z_mm;
  part.tracked_rows = tracked_rows;
  part.truncated = truncated;
  return part;
}

bool PartBuilder::owns(std::int64_t id) const {
  return owns_tracker_id(part_id, merged_ids, merged_count, id);
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
      deshear_(settings.conditioning, settings.cosmos.fit.depth_jump_mm, conditioner_.width()),
      tracker_(tracking_with_shadows(settings), conditioner_.width()),
      row_pool_(std::max(settings.parts.row_blocks, 1),
                static_cast<std::size_t>(std::max(settings.parts.row_block_rows, 1)) *
                    PartRows::record_bytes(conditioner_.width())),
      completed_(static_cast<std::size_t>(std::max(settings.parts.part_queue_slots, 1))),
      returned_(static_cast<std::size_t>(std::max(settings.parts.builders, 1))),
      lost_(static_cast<std::size_t>(PartQueueSettings::kLostPartSlots)),
      speculative_(static_cast<std::size_t>(std::max(settings.parts.builders, 1))),
      speculated_(static_cast<std::size_t>(std::max(settings.parts.builders, 1))),
      speculation_sent_(static_cast<std::size_t>(std::max(settings.parts.builders, 1)), 0),
      speculation_running_(speculation_sent_.size(), 0),
      free_when_speculated_(speculation_sent_.size(), 0),
      row_stamps_(static_cast<std::size_t>(std::max(settings.tracking.link_gap_rows, 0) + 3 +
                                           deshear_.delay())),
      row_belt_(static_cast<std::size_t>(conditioner_.width())),
      row_loop_(static_cast<std::size_t>(conditioner_.width())),
      belt_seen_(static_cast<std::size_t>(conditioner_.width()), 0),
      belt_loop_(static_cast<std::size_t>(conditioner_.width()), 0) {
  for (int b = 0; b < std::max(settings.parts.builders, 1); ++b) {
    builders_.push_back(std::make_unique<PartBuilder>(settings.cosmos, conditioner_.width(),
                                                      settings.max_part_rows,
                                                      settings.conditioning.grid_mm, row_pool_));
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

void ScanLoop::free_builder(int index) {
  const auto k = static_cast<std::size_t>(index);
  if (speculation_running_[k]) {
    // A recognizer worker may still read its rows: it goes back once the worker is done.
    free_when_speculated_[k] = 1;
    return;
  }
  builders_[k]->cosmos.release_rows();
  free_builders_.push_back(index);
}

void ScanLoop::reclaim_returned() {
  int index = -1;
  while (speculated_.try_pop(index)) {
    const auto k = static_cast<std::size_t>(index);
    speculation_running_[k] = 0;
    if (free_when_speculated_[k]) {
      free_when_speculated_[k] = 0;
      free_builder(index);
    }
  }
  while (returned_.try_pop(index)) free_builder(index);
}

std::size_t ScanLoop::builders_at_recognizer() const {
  return builders_.size() - free_builders_.size() - open_builders_.size();
}

bool ScanLoop::recognizer_returns_builders() const {
  const int waiting = builders_waiting_on_open_parts_.load(std::memory_order_acquire);
  return builders_at_recognizer() > static_cast<std::size_t>(std::max(waiting, 0));
}

int ScanLoop::acquire_builder() {
  reclaim_returned();
  // Wait only for builders the recognizer holds: those of open parts come back only when
  // their parts complete, which needs this very loop to go on.
  while (free_builders_.empty() && settings_.wait_for_recognizer && recognizer_returns_builders()) {
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
    const LostPartReason reason = unbuilt->reason;
    unbuilt_.erase(unbuilt);
    if (part.noise) {
      counters_.specks_discarded.fetch_add(1, std::memory_order_relaxed);
      return;
    }
    if (part.merged_into >= 0) {
      // Joined another part: an unbuilt one inherits this one's start; a built one covers it.
      for (UnbuiltPart& into : unbuilt_)
        if (into.id == part.merged_into && first.profile < into.first.profile) into.first = first;
      return;
    }
    const RowStamp& last = stamp_of_row(part.last_row);
    report_lost({reason, first.profile, last.profile, first.encoder_ticks, last.encoder_ticks,
                 last.t_us, width() - 1 - part.column_max, width() - 1 - part.column_min,
                 part.max_z_mm});
    return;
  }
  open_builders_.erase(std::find(open_builders_.begin(), open_builders_.end(), index));
  if (part.merged_into >= 0 || part.noise) {
    counters_.specks_discarded.fetch_add(part.noise ? 1 : 0, std::memory_order_relaxed);
    free_builder(index);
    return;
  }
  PartBuilder& builder = *builders_[static_cast<std::size_t>(index)];
  describe(builder, part);
  // A frozen part cannot take data again (speculate()); should it, the rows its pipeline did
  // not take are reported as a truncated part's unscanned rest, not lost.
  if (speculation_sent_[static_cast<std::size_t>(index)] &&
      builder.last_data_row - builder.first_row >= builder.cosmos.rows())
    builder.truncated = true;
  builder.soft_link_of = part.soft_link_of;
  builder.has_soft_successor = part.has_soft_successor;
  builder.completed_profile = row_profile_;
  builder.completed_ns = monotonic_now_ns();
  counters_.parts_seen.fetch_add(1, std::memory_order_relaxed);
  counters_.parts_truncated.fetch_add(builder.truncated ? 1 : 0, std::memory_order_relaxed);
  while (!completed_.try_push(index)) {
    if (!settings_.wait_for_recognizer) {
      report_lost({LostPartReason::kQueueFull, builder.first_profile,
                   builder.first_profile + builder.rows_added - 1, builder.first_encoder_ticks,
                   builder.last_data_encoder_ticks, builder.last_data_t_us, builder.column_min,
                   builder.column_max, part.max_z_mm});
      free_builder(index);
      return;
    }
    std::this_thread::yield();
  }
}

void ScanLoop::describe(PartBuilder& builder, const TrackedPart& part) {
  builder.column_min = width() - 1 - part.column_max;
  builder.column_max = width() - 1 - part.column_min;
  builder.max_z_mm = part.max_z_mm;
  builder.pixels = part.pixels;
  builder.tracked_rows = part.last_row - part.first_row + 1;
  builder.last_data_row = part.last_row;
  // The pose holds at its last row with data: the empty rows the tracker waited through after
  // it took nothing of the part, so an encoder fault among them must not move its count.
  const RowStamp& last_data = stamp_of_row(part.last_row);
  builder.last_data_profile = last_data.profile;
  builder.last_data_encoder_ticks = last_data.encoder_ticks;
  builder.last_data_t_us = last_data.t_us;
}

void ScanLoop::speculate() {
  if (!settings_.parts.speculative_recognition) return;
  const std::vector<TrackedPart>& open = tracker_.open_parts();
  for (const int index : open_builders_) {
    const auto k = static_cast<std::size_t>(index);
    PartBuilder& builder = *builders_[k];
    if (speculation_sent_[k] || builder.truncated) continue;
    const auto part = std::find_if(open.begin(), open.end(), [&builder](const TrackedPart& p) {
      return p.id == builder.part_id;
    });
    // Only a part that no run can join outright any more, that is no speck, and that shares
    // no row with another open part (which could still merge with it when either completes,
    // part_tracker.hpp).
    const int reach = builder.cosmos.fit_reach_rows();
    if (part == open.end() ||
        row_index_ - part->last_row <= std::max(settings_.tracking.hard_link_gap_rows + 1, reach) ||
        part->pixels < settings_.tracking.min_pixels)
      continue;
    const bool beside_another =
        std::any_of(open.begin(), open.end(), [&part](const TrackedPart& p) {
          return p.id != part->id && p.first_row <= part->last_row + 1;
        });
    if (beside_another) continue;
    // Its pipeline is then finished as the end of an image would finish it: the rows below
    // blank. No row within the fit's reach below its last with data may hold a sample (of a
    // part that starts there), for then the fits of its last rows would have read it. Further
    // down no fit of its rows reads, and the blank rows in between hold no valid fit, so
    // neither the links nor the smoothing carry anything up across them.
    const int after_last = static_cast<int>(part->last_row + 1 - builder.first_row);
    bool blank_below = true;
    for (int r = after_last; r < after_last + reach && blank_below; ++r) {
      const PartRow row = builder.cosmos.row(r);
      blank_below = row.column_end == row.column_begin;
    }
    if (!blank_below) continue;
    describe(builder, *part);
    if (!speculative_.try_push(SpeculativePart{index, builder.built(), part->soft_link_of}))
      continue;
    speculation_sent_[k] = speculation_running_[k] = 1;
  }
}

void ScanLoop::start_parts(const RowStamp& stamp) {
  for (const TrackedPart& part : tracker_.open_parts()) {
    if (part.first_row != row_index_ || builder_of(part.id) >= 0) continue;
    const int index = acquire_builder();
    if (index < 0) {
      // Reported when the tracker completes it (complete()); the tracker never holds more
      // open parts than unbuilt_ has room for.
      if (unbuilt_.size() < unbuilt_.capacity())
        unbuilt_.push_back({part.id, stamp});
      else
        counters_.parts_dropped.fetch_add(1, std::memory_order_relaxed);
      continue;
    }
    PartBuilder& builder = *builders_[static_cast<std::size_t>(index)];
    builder.cosmos.begin_part(x0_loop_mm(),
                              static_cast<double>(stamp.profile) * settings_.conditioning.grid_mm);
    builder.part_id = part.id;
    builder.merged_count = 0;
    builder.first_profile = stamp.profile;
    builder.first_row = row_index_;
    speculation_sent_[static_cast<std::size_t>(index)] = 0;
    builder.rows_added = 0;
    builder.last_data_profile = stamp.profile;
    builder.last_profile = stamp.profile;
    builder.first_encoder_ticks = stamp.encoder_ticks;
    builder.first_t_us = stamp.t_us;
    builder.truncated = false;
    open_builders_.push_back(index);
  }
}

bool ScanLoop::add_row_to(int index, const RowStamp& stamp) {
  PartBuilder& builder = *builders_[static_cast<std::size_t>(index)];
  if (speculation_sent_[static_cast<std::size_t>(index)]) {
    // A recognizer worker may be finishing its pipeline: the row (blank for it, speculate())
    // is counted as the pipeline would have taken it, up to its max_rows.
    if (builder.rows_added >= builder.cosmos.max_rows()) {
      builder.truncated = true;
      return true;
    }
    ++builder.rows_added;
    builder.last_profile = stamp.profile;
    return true;
  }
  AddRowResult added = builder.cosmos.add_row(row_loop_.data(), belt_loop_.data());
  // Unpaced, the blocks of the parts at the recognizer are waited for (as builders are): what
  // is lost must not depend on how fast the recognizer was.
  while (added == AddRowResult::kNoMemory && settings_.wait_for_recognizer &&
         recognizer_returns_builders()) {
    std::this_thread::yield();
    reclaim_returned();
    added = builder.cosmos.add_row(row_loop_.data(), belt_loop_.data());
  }
  if (added == AddRowResult::kTooLong) {
    builder.truncated = true;
    return true;
  }
  if (added == AddRowResult::kNoMemory) {
    // Its rows so far are given back at once, for the other parts; the tracker goes on
    // following it, and its ERROR pose goes out when it completes (complete()).
    counters_.parts_out_of_rows.fetch_add(1, std::memory_order_relaxed);
    if (unbuilt_.size() < unbuilt_.capacity())
      unbuilt_.push_back({builder.part_id,
                          {builder.first_profile, builder.first_encoder_ticks, builder.first_t_us},
                          LostPartReason::kNoRowMemory});
    else
      counters_.parts_dropped.fetch_add(1, std::memory_order_relaxed);
    open_builders_.erase(std::find(open_builders_.begin(), open_builders_.end(), index));
    free_builder(index);
    return false;
  }
  builder.rows_added = builder.cosmos.rows();
  const PartRow row = builder.cosmos.row(builder.cosmos.rows() - 1);
  const std::vector<std::int64_t>& labels = tracker_.row_labels();
  const int last_column = width() - 1;
  for (int c = row.column_begin; c < row.column_end; ++c)
    row.tracker_label[row.at(c)] = labels[static_cast<std::size_t>(last_column - c)];
  builder.last_profile = stamp.profile;
  return true;
}

void ScanLoop::add_row(const float* z_mm, const std::uint8_t* belt, const RowStamp& stamp) {
  std::reverse_copy(z_mm, z_mm + width(), row_loop_.begin());
  if (belt)
    std::reverse_copy(belt, belt + width(), belt_loop_.begin());
  else
    std::fill(belt_loop_.begin(), belt_loop_.end(), 0);
  row_profile_ = stamp.profile;
  for (const TrackedPart& part : tracker_.add_row(z_mm, row_index_, belt)) complete(part);
  counters_.runs_dropped.store(tracker_.dropped_runs(), std::memory_order_relaxed);
  start_parts(stamp);
  for (std::size_t k = 0; k < open_builders_.size();)
    k += add_row_to(open_builders_[k], stamp) ? 1 : 0;
  speculate();
  std::int64_t unfinished_from = stamp.profile + 1;
  for (const int index : open_builders_)
    unfinished_from =
        std::min(unfinished_from, builders_[static_cast<std::size_t>(index)]->first_profile);
  // Unbuilt parts are reported as lost, never recognized: they hold nothing back.
  unfinished_from_profile_.store(unfinished_from, std::memory_order_release);
  ++row_index_;
}

void ScanLoop::process(const Profile& profile) {
  // Builders the recognizer is done with give their row blocks back before this row needs
  // any.
  reclaim_returned();
  // A refused profile becomes an empty row, which keeps the rows in step with the profiles
  // (a part's length and encoder range stay right); the refusal is counted for the operator.
  if (!conditioner_.condition(profile, row_belt_.data(), belt_seen_.data()))
    counters_.profiles_refused.fetch_add(1, std::memory_order_relaxed);
  stamp_of_row(input_index_++) = {static_cast<std::int64_t>(profile.seq), profile.encoder_ticks,
                                  profile.t_us};
  if (!deshear_.active()) {
    add_row(row_belt_.data(), belt_seen_.data(), stamp_of_row(row_index_));
  } else {
    // Out comes the row of the profile the window's rows before this one, under its own
    // stamp (none while the first window fills).
    if (deshear_.push(row_belt_.data(), belt_seen_.data()))
      add_row(deshear_.row(), deshear_.belt(), stamp_of_row(row_index_));
    counters_.samples_too_high.store(deshear_.samples_too_high(), std::memory_order_relaxed);
  }
  counters_.row_blocks_peak.store(row_pool_.peak_blocks_in_use(), std::memory_order_relaxed);
  counters_.profiles.fetch_add(1, std::memory_order_relaxed);
}

void ScanLoop::flush() {
  // The rows the de-shear still holds, fed on with empty input rows under the last profile's
  // stamp: a part right at the stream's end must not lose its last rows.
  const RowStamp last = input_index_ > 0 ? stamp_of_row(input_index_ - 1) : RowStamp{};
  for (int k = deshear_.pending(); k > 0; --k) {
    stamp_of_row(input_index_++) = last;
    if (deshear_.push_empty()) add_row(deshear_.row(), deshear_.belt(), stamp_of_row(row_index_));
  }
  deshear_.clear();
  // Empty rows until every open part has been idle long enough to complete: a stream that
  // ends right behind a part must not lose it. Their stamps are the last profile's.
  std::fill(row_belt_.begin(), row_belt_.end(), Profile::kNoData);
  for (int k = 0; k <= settings_.tracking.link_gap_rows + 1 && !tracker_.open_parts().empty();
       ++k) {
    stamp_of_row(row_index_) = last;
    row_profile_ = last.profile;
    for (const TrackedPart& part : tracker_.add_row(row_belt_.data(), row_index_)) complete(part);
    ++row_index_;
  }
  input_index_ = row_index_;
  if (tracker_.open_parts().empty())
    unfinished_from_profile_.store(std::numeric_limits<std::int64_t>::max(),
                                   std::memory_order_release);
}

}  // namespace cosmos
