#include "calibration/rigid_fit.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace cosmos {

RigidFit fit_rigid_transform(const std::vector<Eigen::Vector3d>& from,
                             const std::vector<Eigen::Vector3d>& to) {
  RigidFit fit;
  if (from.size() < 3 || from.size() != to.size()) return fit;
  const double n = static_cast<double>(from.size());
  Eigen::Vector3d from_mean = Eigen::Vector3d::Zero();
  Eigen::Vector3d to_mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) {
    from_mean += from[i];
    to_mean += to[i];
  }
  from_mean /= n;
  to_mean /= n;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i)
    covariance += (from[i] - from_mean) * (to[i] - to_mean).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  // Collinear points leave a rotation about their line free.
  if (svd.singularValues()(1) < 1e-9 * std::max(1.0, svd.singularValues()(0))) return fit;
  Eigen::Matrix3d correction = Eigen::Matrix3d::Identity();
  // A reflection is no rigid motion: flip the weakest axis.
  if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0) correction(2, 2) = -1.0;
  fit.T_to_from.rotation = svd.matrixV() * correction * svd.matrixU().transpose();
  fit.T_to_from.translation_mm = to_mean - fit.T_to_from.rotation * from_mean;
  double sum = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const double r = (fit.T_to_from.apply(from[i]) - to[i]).norm();
    fit.residual_mm.push_back(r);
    sum += r * r;
  }
  fit.rms_mm = std::sqrt(sum / n);
  fit.ok = true;
  return fit;
}

}  // namespace cosmos
