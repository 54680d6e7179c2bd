#include "apps/recognition_json.hpp"

namespace cosmos {
namespace {

nlohmann::ordered_json part_name(const ModelBase& base, int part) {
  if (part < 0) return nullptr;
  return base.parts[static_cast<std::size_t>(part)].name;
}

nlohmann::ordered_json view_index(const ModelBase& base, int view) {
  if (view < 0) return nullptr;
  return base.views[static_cast<std::size_t>(view)].view_index;
}

}  // namespace

nlohmann::ordered_json recognition_json(const RecognitionResult& result, const ModelBase& base) {
  const bool ok = result.status == RecognitionStatus::kOk;
  nlohmann::ordered_json json;
  json["status"] = to_string(result.status);
  json["reason"] = result.reason;
  json["part"] = part_name(base, ok ? result.part : -1);
  json["view"] = view_index(base, ok ? result.view : -1);
  json["score"] = result.score;
  json["spectral_distance"] = result.spectral_distance;
  json["registration_rms_mm"] = result.registration_rms_mm;
  json["inlier_fraction"] = result.inlier_fraction;
  nlohmann::ordered_json rotation = nlohmann::ordered_json::array();
  for (int r = 0; r < 3; ++r)
    rotation.push_back({result.T_scanner_part.rotation(r, 0), result.T_scanner_part.rotation(r, 1),
                        result.T_scanner_part.rotation(r, 2)});
  json["rotation"] = rotation;
  const Eigen::Vector3d& t = result.T_scanner_part.translation_mm;
  json["translation_mm"] = {t.x(), t.y(), t.z()};
  json["timings_ms"] = {{"features", result.timings.features_ms},
                        {"selection", result.timings.selection_ms},
                        {"matching", result.timings.matching_ms},
                        {"registration", result.timings.registration_ms},
                        {"total", result.timings.total_ms}};
  nlohmann::ordered_json candidates = nlohmann::ordered_json::array();
  for (const RecognitionCandidate& c : result.candidates)
    candidates.push_back({{"part", part_name(base, c.part)},
                          {"view", view_index(base, c.view)},
                          {"spectral_distance", c.spectral_distance},
                          {"goodness", c.goodness},
                          {"rms_mm", c.registered ? nlohmann::ordered_json(c.rms_mm) : nullptr}});
  json["candidates"] = candidates;
  return json;
}

}  // namespace cosmos
