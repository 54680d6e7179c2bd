#include "realtime/web/web_snapshot_store.hpp"

#include <algorithm>

#include "realtime/web/base64.hpp"
#include "realtime/web/pose_json.hpp"
#include "realtime/web/status_json.hpp"

namespace cosmos {
namespace {

nlohmann::ordered_json tile_json(const BeltTile& tile) {
  return {{"first_profile", tile.first_profile},
          {"last_profile", tile.last_profile},
          {"top_px", tile.top_px},
          {"width_px", tile.width_px},
          {"height_px", tile.height_px},
          {"z_max_mm", tile.z_max_mm},
          {"levels_base64", base64_encode(tile.levels)}};
}

}  // namespace

WebSnapshotStore::WebSnapshotStore(const WebViewSettings& settings) : settings_(settings) {}

void WebSnapshotStore::set_geometry(const BeltStripGeometry& geometry) {
  {
    const std::lock_guard lock(mutex_);
    summary_.geometry = geometry;
    ++summary_version_;
  }
  changed_.notify_all();
}

void WebSnapshotStore::update_status(const CellStatus& status) {
  {
    const std::lock_guard lock(mutex_);
    summary_.has_status = true;
    summary_.status = status;
    summary_.head_profile = std::max(summary_.head_profile, status.profiles_acquired - 1);
    ++summary_version_;
    trim_locked();
  }
  changed_.notify_all();
}

void WebSnapshotStore::add_part(const PartRecognition& recognition) {
  BeltStripGeometry geometry;
  {
    const std::lock_guard lock(mutex_);
    geometry = summary_.geometry;
  }
  auto part = std::make_shared<WebPart>();
  part->last_profile = recognition.last_profile;
  part->pose = pose_json(recognition.pose, recognition.first_profile, recognition.last_profile);
  nlohmann::ordered_json event = {{"pose", part->pose}, {"tile", nullptr}};
  if (geometry.belt_columns > 0 && recognition.image.width() > 0)
    event["tile"] =
        tile_json(make_belt_tile(recognition.image, recognition.image_first_profile, geometry));
  part->event_json = event.dump();
  {
    const std::lock_guard lock(mutex_);
    part->index = next_part_index_++;
    parts_.push_back(std::move(part));
    summary_.latency.add(recognition.pose.latency_ms);
    summary_.head_profile = std::max(summary_.head_profile, recognition.last_profile);
    ++summary_version_;
    trim_locked();
  }
  changed_.notify_all();
}

void WebSnapshotStore::close() {
  {
    const std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

// Keeps the recent_poses newest parts and every part still on the strip.
void WebSnapshotStore::trim_locked() {
  const double grid_mm = summary_.geometry.grid_mm > 0 ? summary_.geometry.grid_mm : 1.0;
  const double strip_profiles = settings_.belt_strip_m * 1000.0 / grid_mm;
  while (static_cast<int>(parts_.size()) > settings_.recent_poses &&
         static_cast<double>(summary_.head_profile - parts_.front()->last_profile) > strip_profiles)
    parts_.pop_front();
}

std::string WebSnapshotStore::summary_json(const Summary& summary,
                                           const WebViewSettings& settings) {
  const BeltStripGeometry& g = summary.geometry;
  const nlohmann::ordered_json belt = {
      {"grid_mm", g.grid_mm},
      {"decimation", g.decimation},
      {"mm_per_pixel", g.mm_per_pixel()},
      {"width_px", g.belt_columns > 0 ? g.belt_width_px() : 0},
      {"strip_length_m", settings.belt_strip_m},
      {"head_profile", summary.head_profile},
  };
  const nlohmann::ordered_json document = {
      {"status",
       summary.has_status ? status_json(summary.status) : nlohmann::ordered_json(nullptr)},
      {"pose_latency_ms", summary.latency.json()},
      {"belt", belt},
      {"recent_poses", settings.recent_poses}};
  return document.dump();
}

WebUpdate WebSnapshotStore::wait_for_update(const WebCursor& seen,
                                            std::chrono::milliseconds timeout) const {
  WebUpdate update;
  Summary summary;
  bool summary_changed = false;
  {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, timeout, [&] {
      return closed_ || summary_version_ != seen.summary_version ||
             (!parts_.empty() && parts_.back()->index > seen.part_index);
    });
    update.closed = closed_;
    update.cursor = {summary_version_, seen.part_index};
    if (summary_version_ != seen.summary_version) {
      summary = summary_;
      summary_changed = true;
    }
    for (const auto& part : parts_)
      if (part->index > seen.part_index) update.parts.push_back(part);
    if (!parts_.empty()) update.cursor.part_index = std::max(seen.part_index, parts_.back()->index);
  }
  if (summary_changed) update.summary_json = summary_json(summary, settings_);
  return update;
}

std::string WebSnapshotStore::status_document() const {
  Summary summary;
  {
    const std::lock_guard lock(mutex_);
    summary = summary_;
  }
  return summary_json(summary, settings_);
}

std::string WebSnapshotStore::poses_document() const {
  std::vector<std::shared_ptr<const WebPart>> parts;
  {
    const std::lock_guard lock(mutex_);
    const std::size_t keep =
        std::min(parts_.size(), static_cast<std::size_t>(settings_.recent_poses));
    parts.assign(parts_.end() - static_cast<std::ptrdiff_t>(keep), parts_.end());
  }
  nlohmann::ordered_json poses = nlohmann::ordered_json::array();
  for (auto part = parts.rbegin(); part != parts.rend(); ++part) poses.push_back((*part)->pose);
  return nlohmann::ordered_json{{"poses", poses}}.dump();
}

}  // namespace cosmos
