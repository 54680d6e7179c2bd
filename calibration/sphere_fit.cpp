#include "calibration/sphere_fit.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace cosmos {

SphereFit fit_sphere_known_radius(const std::vector<Eigen::Vector3d>& points, double radius_mm) {
  SphereFit fit;
  if (points.size() < 4) return fit;
  // |p|² = 2 c·p + (r² − |c|²): linear in (c, k).
  Eigen::MatrixXd a(points.size(), 4);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    a.row(static_cast<Eigen::Index>(i)) << 2.0 * points[i].transpose(), 1.0;
    b(static_cast<Eigen::Index>(i)) = points[i].squaredNorm();
  }
  const Eigen::Vector4d solution = a.colPivHouseholderQr().solve(b);
  Eigen::Vector3d centre = solution.head<3>();
  // A nearly flat cap leaves the algebraic centre far off along the view; start above the
  // cap's lowest point by the radius instead when it is.
  if (!centre.allFinite() || std::abs((points.front() - centre).norm() - radius_mm) > radius_mm) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points) mean += p;
    centre = mean / static_cast<double>(points.size()) - Eigen::Vector3d(0, 0, radius_mm * 0.5);
  }
  for (int iteration = 0; iteration < 20; ++iteration) {
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points) {
      const Eigen::Vector3d d = p - centre;
      const double distance = d.norm();
      if (distance < 1e-9) continue;
      const Eigen::Vector3d j = -d / distance;  // ∂(|p − c| − r)/∂c
      const double r = distance - radius_mm;
      jtj += j * j.transpose();
      jtr += j * r;
    }
    const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
    if (!step.allFinite()) return fit;
    centre += step;
    if (step.norm() < 1e-9) break;
  }
  double sum = 0.0;
  for (const Eigen::Vector3d& p : points) {
    const double r = (p - centre).norm() - radius_mm;
    sum += r * r;
  }
  fit.ok = true;
  fit.centre_mm = centre;
  fit.rms_mm = std::sqrt(sum / static_cast<double>(points.size()));
  fit.points = static_cast<int>(points.size());
  return fit;
}

}  // namespace cosmos
