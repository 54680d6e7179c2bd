#pragma once
// The rigid transform that best maps corresponding points of one frame onto another in the
// least-squares sense (Arun, Huang & Blostein's SVD solution; no scale), with the residual of
// every correspondence: the cell calibration's T_cell_scanner from fitted feature centres.
#include <Eigen/Core>
#include <vector>

#include "core/rigid_transform.hpp"

namespace cosmos {

struct RigidFit {
  bool ok = false;
  RigidTransform T_to_from;         // to ≈ T from
  std::vector<double> residual_mm;  // |T from_i − to_i| per correspondence
  double rms_mm = 0.0;
};

// ok false with fewer than 3 pairs, sizes that differ, or collinear points.
RigidFit fit_rigid_transform(const std::vector<Eigen::Vector3d>& from,
                             const std::vector<Eigen::Vector3d>& to);

}  // namespace cosmos
