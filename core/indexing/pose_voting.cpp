#include "core/indexing/pose_voting.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosmos {
namespace {

// The scene's centre: the area-weighted centroid of the patches that can form pairs.
Eigen::Vector3d scene_centre_mm(const CosmosView& scene, const PatchPairKeyParameters& key) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double area = 0;
  for (const Csmp& patch : scene.patches) {
    if (patch.area_mm2 < key.min_patch_area_mm2) continue;
    sum += patch.area_mm2 * patch.centroid_mm;
    area += patch.area_mm2;
  }
  return area > 0 ? Eigen::Vector3d(sum / area) : Eigen::Vector3d::Zero();
}

bool better_pose(const VotedPose& a, const VotedPose& b) {
  return a.votes != b.votes ? a.votes > b.votes : a.part < b.part;
}

}  // namespace

PoseVoter::PoseVoter(const PatchPairTable& table, const PoseVotingParameters& parameters)
    : table_(table), parameters_(parameters) {
  const double half_angle_rad = 0.5 * parameters.same_pose_deg * std::numbers::pi / 180.0;
  min_quaternion_dot_ = static_cast<float>(std::cos(half_angle_rad));
  max_distance2_mm2_ = static_cast<float>(parameters.same_pose_mm * parameters.same_pose_mm);
  hits_.reserve(static_cast<std::size_t>(parameters.max_hits));
  density_.reserve(static_cast<std::size_t>(parameters.max_hits_per_part));
  taken_.reserve(static_cast<std::size_t>(parameters.max_hits_per_part));
  poses_.reserve(static_cast<std::size_t>(parameters.voted_poses + parameters.poses_per_part));
}

std::span<const VotedPose> PoseVoter::vote(const CosmosView& scene) {
  hits_.clear();
  poses_.clear();
  const Eigen::Vector3d centre_scene_mm = scene_centre_mm(scene, table_.key_parameters());
  collect_hits(scene, centre_scene_mm);
  // Each part's hits together, the heaviest first.
  std::sort(hits_.begin(), hits_.end(), [](const Hit& a, const Hit& b) {
    if (a.part != b.part) return a.part < b.part;
    if (a.weight != b.weight) return a.weight > b.weight;
    return a.order < b.order;
  });
  for (std::size_t first = 0; first < hits_.size();) {
    std::size_t end = first;
    while (end < hits_.size() && hits_[end].part == hits_[first].part) ++end;
    find_modes(first, end, centre_scene_mm);
    first = end;
  }
  return poses_;
}

void PoseVoter::collect_hits(const CosmosView& scene, const Eigen::Vector3d& centre_scene_mm) {
  const PatchPairKeyParameters& key = table_.key_parameters();
  const std::size_t capacity = static_cast<std::size_t>(parameters_.max_hits);
  std::array<int, kMaxNearbyPatchPairKeys> keys{};
  // One order of the scene pair meets both orders stored of the model pair.
  for_each_patch_pair(scene, key, [&](const Csmp& a, const Csmp& b) {
    const std::optional<PatchPairFeature> feature = patch_pair_feature(a, b, key);
    if (!feature) return;
    const int key_count = nearby_patch_pair_keys(*feature, key, keys);
    std::size_t entries = 0;
    for (int k = 0; k < key_count; ++k) entries += table_.entries(keys[k]).size();
    if (entries == 0) return;
    const std::size_t step =
        (entries + static_cast<std::size_t>(parameters_.max_entries_per_pair) - 1) /
        static_cast<std::size_t>(parameters_.max_entries_per_pair);
    const float weight =
        static_cast<float>(static_cast<double>(step) / std::sqrt(static_cast<double>(entries)));
    const RigidTransform T_pair_scene = feature->T_view_pair.inverse();
    const Eigen::Quaternionf q_pair_scene =
        Eigen::Quaterniond(T_pair_scene.rotation).normalized().cast<float>();
    const Eigen::Vector3f centre_pair_mm = T_pair_scene.apply(centre_scene_mm).cast<float>();
    std::size_t index = 0;
    for (int k = 0; k < key_count; ++k)
      for (const IndexedPatchPair& model : table_.entries(keys[k])) {
        if (index++ % step != 0) continue;
        if (hits_.size() == capacity) return;
        Hit hit;
        hit.q_part_scene = model.q_part_pair * q_pair_scene;
        hit.centre_part_mm = model.q_part_pair * centre_pair_mm + model.t_part_pair_mm;
        hit.weight = weight;
        hit.part = model.part;
        hit.order = static_cast<std::int32_t>(hits_.size());
        hits_.push_back(hit);
      }
  });
}

bool PoseVoter::same_pose(const Hit& a, const Hit& b) const {
  return std::abs(a.q_part_scene.dot(b.q_part_scene)) >= min_quaternion_dot_ &&
         (a.centre_part_mm - b.centre_part_mm).squaredNorm() <= max_distance2_mm2_;
}

void PoseVoter::find_modes(std::size_t first, std::size_t end,
                           const Eigen::Vector3d& centre_scene_mm) {
  const std::size_t count =
      std::min(end - first, static_cast<std::size_t>(parameters_.max_hits_per_part));
  const Hit* hits = hits_.data() + first;
  density_.assign(count, 0.0f);
  taken_.assign(count, 0);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = i; j < count; ++j)
      if (same_pose(hits[i], hits[j])) {
        density_[i] += hits[j].weight;
        if (j != i) density_[j] += hits[i].weight;
      }
  for (int mode = 0; mode < parameters_.poses_per_part; ++mode) {
    std::size_t best = count;
    for (std::size_t i = 0; i < count; ++i)
      if (!taken_[i] && (best == count || density_[i] > density_[best])) best = i;
    if (best == count) return;
    // The mode's pose: the weighted mean of the hits around it (quaternions on its side).
    Eigen::Vector4f q_sum = Eigen::Vector4f::Zero();
    Eigen::Vector3f centre_sum = Eigen::Vector3f::Zero();
    float weight_sum = 0;
    for (std::size_t j = 0; j < count; ++j) {
      if (!same_pose(hits[best], hits[j])) continue;
      const float sign = hits[best].q_part_scene.dot(hits[j].q_part_scene) < 0 ? -1.0f : 1.0f;
      q_sum += sign * hits[j].weight * hits[j].q_part_scene.coeffs();
      centre_sum += hits[j].weight * hits[j].centre_part_mm;
      weight_sum += hits[j].weight;
      taken_[j] = 1;
    }
    VotedPose pose;
    pose.part = hits[best].part;
    pose.votes = density_[best];
    pose.T_part_scene.rotation =
        Eigen::Quaternionf(q_sum).normalized().toRotationMatrix().cast<double>();
    const Eigen::Vector3d centre_part_mm = (centre_sum / weight_sum).cast<double>();
    pose.T_part_scene.translation_mm =
        centre_part_mm - pose.T_part_scene.rotation * centre_scene_mm;
    // Kept best first, at most voted_poses of them.
    const auto at = std::upper_bound(poses_.begin(), poses_.end(), pose, better_pose);
    if (at - poses_.begin() >= parameters_.voted_poses) continue;
    poses_.insert(at, pose);
    if (poses_.size() > static_cast<std::size_t>(parameters_.voted_poses)) poses_.pop_back();
  }
}

}  // namespace cosmos
