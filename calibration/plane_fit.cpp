#include "calibration/plane_fit.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace cosmos {
namespace {

// SplitMix64: the fit's own seeded stream (calibration does not see the simulator's).
std::uint64_t next_random(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

std::vector<Eigen::Vector3d> within(const std::vector<Eigen::Vector3d>& points, const PlaneFit& fit,
                                    double distance_mm) {
  std::vector<Eigen::Vector3d> kept;
  for (const Eigen::Vector3d& p : points)
    if (std::abs(fit.distance_mm(p)) <= distance_mm) kept.push_back(p);
  return kept;
}

}  // namespace

PlaneFit fit_plane_least_squares(const std::vector<Eigen::Vector3d>& points) {
  PlaneFit fit;
  if (points.size() < 3) return fit;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points) scatter += (p - centroid) * (p - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  // A line of points has two vanishing eigenvalues: no plane.
  if (solver.eigenvalues()(1) <= 1e-12 * std::max(1.0, solver.eigenvalues()(2))) return fit;
  fit.normal = solver.eigenvectors().col(0).normalized();
  fit.offset_mm = fit.normal.dot(centroid);
  fit.rms_mm = std::sqrt(std::max(0.0, solver.eigenvalues()(0)) / points.size());
  fit.inliers = static_cast<int>(points.size());
  fit.ok = true;
  return fit;
}

PlaneFit fit_plane_robust(const std::vector<Eigen::Vector3d>& points,
                          const PlaneFitSettings& settings) {
  PlaneFit best;
  if (points.size() < 3) return best;
  std::uint64_t state = settings.seed;
  const auto n = static_cast<std::uint64_t>(points.size());
  int best_count = 0;
  for (int iteration = 0; iteration < settings.iterations; ++iteration) {
    const Eigen::Vector3d& a = points[next_random(state) % n];
    const Eigen::Vector3d& b = points[next_random(state) % n];
    const Eigen::Vector3d& c = points[next_random(state) % n];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() < 1e-9) continue;
    PlaneFit candidate;
    candidate.normal = normal.normalized();
    candidate.offset_mm = candidate.normal.dot(a);
    int count = 0;
    for (const Eigen::Vector3d& p : points)
      count += std::abs(candidate.distance_mm(p)) <= settings.inlier_distance_mm;
    if (count > best_count) {
      best_count = count;
      best = candidate;
    }
  }
  if (best_count < 3) return PlaneFit{};
  PlaneFit refined = fit_plane_least_squares(within(points, best, settings.inlier_distance_mm));
  if (!refined.ok) return refined;
  refined = fit_plane_least_squares(within(points, refined, settings.inlier_distance_mm));
  return refined;
}

}  // namespace cosmos
