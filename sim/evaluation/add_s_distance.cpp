#include "sim/evaluation/add_s_distance.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cosmos {
namespace {

// Below this size a range is scanned linearly: recursing further costs more than it prunes.
constexpr int kLeafPoints = 8;

}  // namespace

AddSDistance::AddSDistance(std::span<const Eigen::Vector3d> model_points_mm)
    : points_mm_(model_points_mm.begin(), model_points_mm.end()),
      split_axis_(model_points_mm.size(), 0) {
  build(0, static_cast<int>(points_mm_.size()));
}

AddSDistance::AddSDistance(std::span<const Eigen::Vector3d> model_points_mm,
                           const TriangleMesh& mesh)
    : AddSDistance(model_points_mm, std::make_unique<const MeshSurfaceDistance>(mesh)) {}

AddSDistance::AddSDistance(std::span<const Eigen::Vector3d> model_points_mm,
                           std::unique_ptr<const MeshSurfaceDistance> surface)
    : points_mm_(model_points_mm.begin(), model_points_mm.end()), surface_(std::move(surface)) {}

// Splits [begin, end) at its middle along the axis of largest extent, so that every point
// before the middle is <= the middle point on that axis and every point after it is >=.
void AddSDistance::build(int begin, int end) {
  if (end - begin <= kLeafPoints) return;
  Eigen::Vector3d low = points_mm_[static_cast<std::size_t>(begin)], high = low;
  for (int i = begin; i < end; ++i) {
    low = low.cwiseMin(points_mm_[static_cast<std::size_t>(i)]);
    high = high.cwiseMax(points_mm_[static_cast<std::size_t>(i)]);
  }
  int axis = 0;
  (high - low).maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(
      points_mm_.begin() + begin, points_mm_.begin() + middle, points_mm_.begin() + end,
      [axis](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a[axis] < b[axis]; });
  split_axis_[static_cast<std::size_t>(middle)] = static_cast<std::uint8_t>(axis);
  build(begin, middle);
  build(middle + 1, end);
}

void AddSDistance::search(int begin, int end, const Eigen::Vector3d& query_mm,
                          double& best_mm2) const {
  if (end - begin <= kLeafPoints) {
    for (int i = begin; i < end; ++i)
      best_mm2 =
          std::min(best_mm2, (points_mm_[static_cast<std::size_t>(i)] - query_mm).squaredNorm());
    return;
  }
  const int middle = begin + (end - begin) / 2;
  const Eigen::Vector3d& split_point = points_mm_[static_cast<std::size_t>(middle)];
  const int axis = split_axis_[static_cast<std::size_t>(middle)];
  best_mm2 = std::min(best_mm2, (split_point - query_mm).squaredNorm());
  const double offset_mm = query_mm[axis] - split_point[axis];
  const bool below = offset_mm < 0;
  search(below ? begin : middle + 1, below ? middle : end, query_mm, best_mm2);
  // The far side is at least |offset| away along the split axis.
  if (offset_mm * offset_mm < best_mm2)
    search(below ? middle + 1 : begin, below ? end : middle, query_mm, best_mm2);
}

double AddSDistance::nearest_squared_mm2(const Eigen::Vector3d& query_mm) const {
  if (surface_) return surface_->nearest_squared_mm2(query_mm);
  double best_mm2 = std::numeric_limits<double>::infinity();
  search(0, static_cast<int>(points_mm_.size()), query_mm, best_mm2);
  return best_mm2;
}

double AddSDistance::add_s_mm(const RigidPose& truth, const RigidPose& estimate) const {
  if (points_mm_.empty()) return 0;
  // min_q |(R_t p + t_t) - (R_e q + t_e)| = min_q |R_e^T (R_t p + t_t - t_e) - q| for a rotation
  // R_e, so the true image of p is brought into the part frame where the tree lives.
  const Eigen::Matrix3d R_estimate_true = estimate.R.transpose() * truth.R;
  const Eigen::Vector3d t_estimate_true_mm = estimate.R.transpose() * (truth.t_mm - estimate.t_mm);
  double sum_mm = 0;
  for (const Eigen::Vector3d& p : points_mm_)
    sum_mm += std::sqrt(nearest_squared_mm2(R_estimate_true * p + t_estimate_true_mm));
  return sum_mm / static_cast<double>(points_mm_.size());
}

double add_mm(std::span<const Eigen::Vector3d> model_points_mm, const RigidPose& truth,
              const RigidPose& estimate) {
  if (model_points_mm.empty()) return 0;
  double sum_mm = 0;
  for (const Eigen::Vector3d& p : model_points_mm)
    sum_mm += ((truth.R * p + truth.t_mm) - (estimate.R * p + estimate.t_mm)).norm();
  return sum_mm / static_cast<double>(model_points_mm.size());
}

}  // namespace cosmos
