#include "realtime/loop/part_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace cosmos {

PartTracker::PartTracker(const PartTrackerParameters& parameters, int width)
    : parameters_(parameters),
      width_(width),
      labels_(width, -1),
      belt_row_(width, -1),
      scratch_(width, -1) {
  previous_runs_.reserve(parameters.max_runs_per_row);
  runs_.reserve(parameters.max_runs_per_row);
  open_.reserve(parameters.max_open_parts);
  completed_.reserve(parameters.max_open_parts);
  merges_.reserve(parameters.max_runs_per_row);
}

int PartTracker::open_index(std::int64_t part) const {
  for (std::size_t k = 0; k < open_.size(); ++k)
    if (open_[k].id == part) return static_cast<int>(k);
  return -1;
}

std::int64_t PartTracker::resolve(std::int64_t part) const {
  for (const auto& [absorbed, kept] : merges_)
    if (absorbed == part) return resolve(kept);
  return part;
}

void PartTracker::merge(std::int64_t keep, std::int64_t absorbed) {
  TrackedPart& kept = open_[open_index(keep)];
  const int index = open_index(absorbed);
  TrackedPart gone = open_[index];
  if (gone.first_row < kept.first_row) kept.leading_z_mm = gone.leading_z_mm;
  if (kept.soft_link_of < 0 && gone.soft_link_of != keep) kept.soft_link_of = gone.soft_link_of;
  kept.has_soft_successor = kept.has_soft_successor || gone.has_soft_successor;
  kept.first_row = std::min(kept.first_row, gone.first_row);
  kept.column_min = std::min(kept.column_min, gone.column_min);
  kept.column_max = std::max(kept.column_max, gone.column_max);
  kept.last_row = std::max(kept.last_row, gone.last_row);
  kept.pixels += gone.pixels;
  kept.max_z_mm = std::max(kept.max_z_mm, gone.max_z_mm);
  gone.merged_into = keep;
  completed_.push_back(gone);
  open_.erase(open_.begin() + index);  // no allocation: erase within capacity
  merges_.emplace_back(absorbed, keep);
}

void PartTracker::join_small_pieces(std::int64_t row_index) {
  for (bool joined = true; joined;) {
    joined = false;
    for (std::size_t k = 0; k < open_.size() && !joined; ++k) {
      const TrackedPart& piece = open_[k];
      if (!piece.has_soft_successor || piece.pixels >= parameters_.min_pixels ||
          !idle(piece, row_index))
        continue;
      std::int64_t successor = -1;
      bool other_successor = false;
      for (const TrackedPart& part : open_) {
        if (part.soft_link_of != piece.id) continue;
        if (successor < 0) {
          successor = part.id;
        } else {
          other_successor = true;
        }
      }
      if (successor < 0) continue;
      const std::int64_t keep = piece.id;  // the older: successors start after its last row
      const bool successor_has_successor = open_[open_index(successor)].has_soft_successor;
      merge(keep, successor);
      TrackedPart& kept = open_[open_index(keep)];
      kept.has_soft_successor = successor_has_successor || other_successor;
      for (TrackedPart& part : open_)
        if (part.soft_link_of == successor) part.soft_link_of = keep;
      joined = true;
    }
  }
}

bool PartTracker::idle(const TrackedPart& part, std::int64_t row_index) const {
  return row_index - part.last_row > parameters_.link_gap_rows;
}

std::int64_t PartTracker::shadow_rows(float z_mm) const {
  // 15 % and 4 rows: the camera's perspective lengthens the shadow of a feature off its axis,
  // and the leading rows seen need not hold the very edge that casts it.
  constexpr double kSlack = 1.15;
  constexpr double kMarginRows = 4;
  return static_cast<std::int64_t>(
      std::ceil(static_cast<double>(z_mm) * parameters_.shadow_rows_per_mm * kSlack + kMarginRows));
}

std::int64_t PartTracker::belt_seen_row(int begin, int end) {
  const int n = end - begin;
  if (n <= 0) return -1;
  std::copy(belt_row_.begin() + begin, belt_row_.begin() + end, scratch_.begin());
  const auto kth = scratch_.begin() + (n * 3) / 10;  // 70 % of the columns are at least this
  std::nth_element(scratch_.begin(), kth, scratch_.begin() + n, std::greater<>());
  return *kth;
}

bool PartTracker::footprints_overlap(const TrackedPart& a, const TrackedPart& b) const {
  const int columns = parameters_.link_gap_columns + 1;
  std::int64_t rows = parameters_.link_gap_rows + 1;
  if (parameters_.shadow_rows_per_mm > 0) {
    // One after the other: joined only across what the later one's leading end shadows.
    // Only pieces side by side (sharing rows) join here: one after the other, a gap lies
    // between them, which the soft links judge (add_row).
    rows = 1;
  }
  return a.column_min <= b.column_max + columns && b.column_min <= a.column_max + columns &&
         a.first_row <= b.last_row + rows && b.first_row <= a.last_row + rows;
}

const std::vector<TrackedPart>& PartTracker::add_row(const float* z_mm, std::int64_t row_index,
                                                     const std::uint8_t* belt) {
  completed_.clear();
  merges_.clear();
  runs_.clear();
  for (int column = 0; column < width_;) {
    if (std::isnan(z_mm[column])) {
      ++column;
      continue;
    }
    const int begin = column;
    while (column < width_ && !std::isnan(z_mm[column])) ++column;
    if (static_cast<int>(runs_.size()) < parameters_.max_runs_per_row) {
      runs_.push_back({begin, column, -1});
    } else {
      ++dropped_runs_;
    }
  }
  // Link each run to the parts of the previous row's runs it touches; merge when several.
  const int gap = parameters_.link_gap_columns + 1;  // +1: diagonal neighbours touch
  for (Run& run : runs_) {
    for (const Run& above : previous_runs_) {
      if (above.part < 0 || above.end + gap <= run.begin || run.end + gap <= above.begin) continue;
      const std::int64_t part = resolve(above.part);
      if (open_index(part) < 0) continue;
      if (run.part < 0) {
        run.part = part;
      } else if (resolve(run.part) != part) {
        const std::int64_t a = resolve(run.part);
        merge(std::min(a, part), std::max(a, part));  // the earlier part keeps its id
        run.part = std::min(a, part);
      }
    }
    // Shadows and dropouts split one part's surface: a run near a part seen in the last
    // link_gap_rows rows (within its column extent and link_gap_columns) belongs to it.
    float run_z_mm = 0;
    if (parameters_.shadow_rows_per_mm > 0)
      for (int c = run.begin; c < run.end; ++c) run_z_mm = std::max(run_z_mm, z_mm[c]);
    std::int64_t soft_link = -1;
    for (std::size_t k = 0; run.part < 0 && k < open_.size(); ++k) {
      TrackedPart& part = open_[k];
      if (row_index - part.last_row > parameters_.link_gap_rows + 1) continue;
      // Only as far as this run's height can have shadowed: a longer gap is belt.
      if (parameters_.shadow_rows_per_mm > 0 &&
          row_index - part.last_row - 1 > shadow_rows(run_z_mm))
        continue;
      // Nor across belt seen in front of the run since the part's last row.
      if (belt && row_index - part.last_row > 1 &&
          belt_seen_row(run.begin, run.end) > part.last_row)
        continue;
      if (part.column_max + gap < run.begin || run.end - 1 + gap < part.column_min) continue;
      // A gap longer than a dropout: a soft link, the run starts a piece of its own.
      if (parameters_.shadow_rows_per_mm > 0 &&
          row_index - part.last_row - 1 > parameters_.hard_link_gap_rows) {
        if (soft_link < 0) soft_link = part.id;
        part.has_soft_successor = true;
        continue;
      }
      run.part = part.id;
    }
    if (run.part < 0) {
      if (static_cast<int>(open_.size()) >= parameters_.max_open_parts) {
        ++dropped_runs_;
        continue;
      }
      TrackedPart part;
      part.id = next_id_++;
      part.first_row = row_index;
      part.column_min = run.begin;
      part.column_max = run.end - 1;
      part.soft_link_of = soft_link;
      open_.push_back(part);
      run.part = part.id;
    }
  }
  // Account the row.
  std::fill(labels_.begin(), labels_.end(), -1);
  for (Run& run : runs_) {
    if (run.part < 0) continue;
    run.part = resolve(run.part);
    TrackedPart& part = open_[open_index(run.part)];
    part.last_row = row_index;
    part.column_min = std::min(part.column_min, run.begin);
    part.column_max = std::max(part.column_max, run.end - 1);
    part.pixels += run.end - run.begin;
    const bool leading = row_index - part.first_row < kLeadingRows;
    for (int c = run.begin; c < run.end; ++c) {
      part.max_z_mm = std::max(part.max_z_mm, z_mm[c]);
      if (leading) part.leading_z_mm = std::max(part.leading_z_mm, z_mm[c]);
    }
    std::fill(labels_.begin() + run.begin, labels_.begin() + run.end, run.part);
  }
  // A part no row has touched for link_gap_rows is complete, unless its footprint overlaps
  // an open part's: then it is a piece of that part (a horn or leg cut off by the shadows
  // over its whole length), and joins it.
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t k = 0; k < open_.size() && !merged; ++k) {
      if (!idle(open_[k], row_index)) continue;
      for (std::size_t j = 0; j < open_.size() && !merged; ++j) {
        if (j == k || !footprints_overlap(open_[k], open_[j])) continue;
        merge(std::min(open_[k].id, open_[j].id), std::max(open_[k].id, open_[j].id));
        merged = true;
      }
    }
  }
  join_small_pieces(row_index);
  for (std::size_t k = open_.size(); k-- > 0;) {
    if (!idle(open_[k], row_index)) continue;
    TrackedPart done = open_[k];
    // A thin part seen edge-on has few pixels, but spans many rows or columns; a speck neither.
    done.noise = done.pixels < parameters_.min_pixels &&
                 done.last_row - done.first_row + 1 < parameters_.min_pixels &&
                 done.column_max - done.column_min + 1 < parameters_.min_pixels;
    completed_.push_back(done);
    open_.erase(open_.begin() + static_cast<long>(k));
  }
  if (belt)
    for (int c = 0; c < width_; ++c)
      if (belt[c]) belt_row_[static_cast<std::size_t>(c)] = row_index;
  // Parts merged away first, so that the part each joined knows it before it completes in
  // the same row (a part always merges into an older one, so the newest first resolves chains);
  // then the completed ones, oldest first.
  std::sort(completed_.begin(), completed_.end(), [](const TrackedPart& a, const TrackedPart& b) {
    const bool a_merged = a.merged_into >= 0, b_merged = b.merged_into >= 0;
    if (a_merged != b_merged) return a_merged;
    return a_merged ? a.id > b.id : a.id < b.id;
  });
  std::swap(previous_runs_, runs_);
  return completed_;
}

}  // namespace cosmos
