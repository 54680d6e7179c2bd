#include "core/registration/view_registration.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "core/registration/tangent_plane_correspondence.hpp"

namespace cosmos {
namespace {

// The weakest direction of the normal equations gets less than this mean squared constraint
// per unit weight (see solve_increment): some combination of the 6 parameters is fixed only
// by noise (a plane, a cylinder, a sphere, §6.8). 1e-3 is the constraint that normals varying
// by ~2 degrees about that direction would give.
constexpr double kMinMeanConstraint = 1e-3;
constexpr int kMaxWeakDirections = 3;
// Median absolute deviation to standard deviation for Gaussian residuals.
constexpr double kMadToSigma = 1.4826;

// A correspondence that was an inlier in the previous pass stays one up to this multiple of
// the rejection distance: without the band, a point sitting on the threshold can leave, move
// T (and the median-based threshold) so that it re-enters, and so on.
constexpr double kInlierHysteresis = 1.25;

struct Correspondence {
  int scene_index;
  Eigen::Vector3d point_mm;  // T p_i
  Eigen::Vector3d normal;    // model normal at q_i
  double distance_mm;        // d_s
  double weight;
};

bool valid_input(const RegistrationPoints& scene, const RegistrationPoints& model,
                 const RegistrationParameters& p) {
  if (scene.size() == 0 || model.size() == 0) return false;
  if (p.max_iterations < 1 || p.max_intersection_steps < 1 || p.min_inliers < 6) return false;
  return p.max_correspondence_distance_mm > 0 && p.min_rejection_distance_mm > 0 &&
         p.max_normal_angle_deg > 0 && p.rejection_mad_factor > 0 && p.min_distance_sigma_mm > 0;
}

// Fewer control points than this per share are not worth handing to another thread.
constexpr int kMinPointsPerShare = 256;

// Step (i) of §6.4 for every control point; candidates that pass the geometric tests (line
// met the model close enough, compatible normals), in the points' order. Returns the
// intersection steps spent. A point's correspondence depends on it alone: the points are
// taken in contiguous shares on `tasks`, their lists joined in share order.
long find_correspondences(const RegistrationPoints& scene, const RegistrationPoints& model,
                          const RigidTransform& T_model_scene, const RegistrationParameters& p,
                          std::vector<Correspondence>& out, const TaskRunner& tasks) {
  out.clear();
  const double min_normal_cosine = std::cos(p.max_normal_angle_deg * std::numbers::pi / 180.0);
  const Eigen::Vector3d scene_view_axis = T_model_scene.rotation.col(2);
  const double scene_sigma2 = scene.z_noise_sigma_mm * scene.z_noise_sigma_mm;
  const double min_variance = p.min_distance_sigma_mm * p.min_distance_sigma_mm;
  const auto correspond = [&](int begin, int end, std::vector<Correspondence>& into) {
    long steps = 0;
    for (int i = begin; i < end; ++i) {
      const Eigen::Vector3d point = T_model_scene.apply(scene.position_mm.col(i));
      const Eigen::Vector3d normal = T_model_scene.rotate(scene.normal.col(i));
      TangentPlaneCorrespondence c;
      const CorrespondenceStatus status =
          find_tangent_plane(model, point, normal, p.max_intersection_steps, c);
      steps += c.steps;
      if (status != CorrespondenceStatus::kFound) continue;
      if (c.travel_mm > p.max_correspondence_distance_mm) continue;
      if (c.model_normal.dot(normal) < min_normal_cosine) continue;
      double weight = 1.0;
      if (p.estimator == RegistrationEstimator::kMinimumVariance) {
        const double scene_height_variance = scene_sigma2 * scene.fit_cofactor(kHeight, kHeight);
        const double variance =
            distance_variance_mm2(model, c, point, scene_height_variance, scene_view_axis);
        weight = 1.0 / std::max(variance, min_variance);
      }
      into.push_back({i, point, c.model_normal, c.distance_mm, weight});
    }
    return steps;
  };
  const int shares = share_count(tasks, scene.size(), kMinPointsPerShare);
  if (shares == 1) return correspond(0, scene.size(), out);
  std::vector<std::vector<Correspondence>> share_out(static_cast<std::size_t>(shares));
  std::vector<long> share_steps(static_cast<std::size_t>(shares), 0);
  run_in_shares(tasks, scene.size(), shares, [&](int share, int begin, int end) {
    share_steps[static_cast<std::size_t>(share)] =
        correspond(begin, end, share_out[static_cast<std::size_t>(share)]);
  });
  long steps = 0;
  for (int share = 0; share < shares; ++share) {
    const std::vector<Correspondence>& part = share_out[static_cast<std::size_t>(share)];
    out.insert(out.end(), part.begin(), part.end());
    steps += share_steps[static_cast<std::size_t>(share)];
  }
  return steps;
}

double rejection_distance_mm(const std::vector<Correspondence>& candidates,
                             const RegistrationParameters& p) {
  std::vector<double> magnitudes;
  magnitudes.reserve(candidates.size());
  for (const Correspondence& c : candidates) magnitudes.push_back(std::abs(c.distance_mm));
  const auto middle = magnitudes.begin() + static_cast<std::ptrdiff_t>(magnitudes.size() / 2);
  std::nth_element(magnitudes.begin(), middle, magnitudes.end());
  return std::clamp(p.rejection_mad_factor * kMadToSigma * *middle, p.min_rejection_distance_mm,
                    p.max_correspondence_distance_mm);
}

// ok: every direction constrained or only 1-2 weak (a cylinder); planar: 3 or more weak.
enum class SolveStatus { kOk, kPlanar, kUnconstrained };

struct Increment {
  RigidTransform T_new_old;
  double rotation_rad = 0.0;
  double centroid_shift_mm = 0.0;  // how far the inliers' centroid moves
  // RegistrationResult's weakest motion, of this pass.
  Eigen::Matrix<double, 6, 1> weakest_motion = Eigen::Matrix<double, 6, 1>::Zero();
  double lever_mm = 1.0;
  double weakest_constraint = 0.0;
  Eigen::Vector3d centroid_mm = Eigen::Vector3d::Zero();
};

// Step (ii): d_s after a small motion (omega about the centroid c, then tau) is, to first
// order, d_s + ((T p - c) x n) . omega + n . tau; the weighted least-squares increment.
// (The cross product is written out: GCC 12 misreads Eigen's AVX cross() as out of bounds.)
// `belt`: the belt's rows (belt_contact.hpp); they constrain the step but, not being scene
// points, neither move the centroid nor count in the conditioning below.
SolveStatus solve_increment(const std::vector<Correspondence>& inliers,
                            const std::vector<Correspondence>& belt, Increment& increment) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Correspondence& c : inliers) centroid += c.point_mm;
  centroid /= static_cast<double>(inliers.size());
  Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
  const auto add_row = [&](const Correspondence& c) {
    const Eigen::Vector3d lever_mm = c.point_mm - centroid;
    Eigen::Matrix<double, 6, 1> J;
    J(0) = lever_mm.y() * c.normal.z() - lever_mm.z() * c.normal.y();
    J(1) = lever_mm.z() * c.normal.x() - lever_mm.x() * c.normal.z();
    J(2) = lever_mm.x() * c.normal.y() - lever_mm.y() * c.normal.x();
    J.tail<3>() = c.normal;
    // The full outer product: fixed-size and inlined, it is cheaper than rankUpdate's call.
    H.noalias() += (c.weight * J) * J.transpose();
    g += c.weight * c.distance_mm * J;
  };
  for (const Correspondence& c : inliers) add_row(c);
  for (const Correspondence& c : belt) add_row(c);
  // Conditioning in units that do not depend on the part's size: rotations scaled by the RMS
  // lever arm, so each eigenvalue is a weighted sum of squared unit-free constraints; divided
  // by the total weight it is the mean squared constraint the weakest direction gets.
  double lever2 = 0.0, total_weight = 0.0;
  for (const Correspondence& c : inliers) {
    lever2 += c.weight * (c.point_mm - centroid).squaredNorm();
    total_weight += c.weight;
  }
  Eigen::Matrix<double, 6, 1> scale = Eigen::Matrix<double, 6, 1>::Ones();
  scale.head<3>().setConstant(1.0 / std::sqrt(std::max(lever2 / total_weight, 1e-300)));
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(scale.asDiagonal() * H *
                                                                         scale.asDiagonal());
  const double min_constraint = kMinMeanConstraint * total_weight;
  increment.weakest_motion = eigen.eigenvectors().col(0);
  increment.lever_mm = 1.0 / scale(0);
  increment.weakest_constraint = eigen.eigenvalues()(0) / total_weight;
  increment.centroid_mm = centroid;
  int weak_directions = 0;
  for (int k = 0; k < 6; ++k) weak_directions += eigen.eigenvalues()(k) > min_constraint ? 0 : 1;
  if (weak_directions == 6) return SolveStatus::kUnconstrained;
  Eigen::Matrix<double, 6, 1> x;
  if (weak_directions == 0) {
    x = H.ldlt().solve(-g);
  } else {
    // A surface of revolution or a cylinder leaves one or two directions to noise, a plane
    // three (§6.8): step only in the constrained ones (truncated eigen-solve in the scaled
    // parameters) and keep the rest of the current estimate, which the initial pose supplied.
    // From a rough start the inliers may be one flat face at first; the constrained step
    // brings in more of the surface, and the next pass constrains everything.
    const Eigen::Matrix<double, 6, 6>& V = eigen.eigenvectors();
    const Eigen::Matrix<double, 6, 1> scaled_g = scale.asDiagonal() * g;
    Eigen::Matrix<double, 6, 1> scaled_x = Eigen::Matrix<double, 6, 1>::Zero();
    for (int k = weak_directions; k < 6; ++k)
      scaled_x -= V.col(k) * (V.col(k).dot(scaled_g) / eigen.eigenvalues()(k));
    x = scale.asDiagonal() * scaled_x;
  }
  const Eigen::Matrix3d rotation = rotation_from_vector(x.head<3>());
  increment.T_new_old = {rotation, centroid - rotation * centroid + x.tail<3>()};
  increment.rotation_rad = x.head<3>().norm();
  increment.centroid_shift_mm = x.tail<3>().norm();
  return weak_directions >= kMaxWeakDirections ? SolveStatus::kPlanar : SolveStatus::kOk;
}

}  // namespace

RegistrationResult register_views(const RegistrationPoints& scene, const RegistrationPoints& model,
                                  const RigidTransform& T_model_scene_initial,
                                  const RegistrationParameters& parameters, const TaskRunner& tasks,
                                  const BeltContact& belt) {
  RegistrationResult result;
  result.T_model_scene = T_model_scene_initial;
  if (!valid_input(scene, model, parameters)) return result;

  std::vector<Correspondence> candidates, inliers, belt_rows;
  std::vector<std::uint8_t> was_inlier(static_cast<std::size_t>(scene.size()), 0);
  std::vector<std::uint8_t> is_inlier(was_inlier.size(), 0);
  candidates.reserve(static_cast<std::size_t>(scene.size()));
  inliers.reserve(static_cast<std::size_t>(scene.size()));
  belt_rows.reserve(belt.hull_vertices_part_mm.size());
  const Eigen::Vector3d scene_centroid_mm = scene.position_mm.rowwise().mean();
  RigidTransform T_last = result.T_model_scene;
  bool planar = false;  // the last pass left 3 or more directions free
  result.status = RegistrationStatus::kIterationBudgetExhausted;
  for (int iteration = 1; iteration <= parameters.max_iterations; ++iteration) {
    result.intersection_steps +=
        find_correspondences(scene, model, result.T_model_scene, parameters, candidates, tasks);
    if (static_cast<int>(candidates.size()) < parameters.min_inliers) {
      result.status = RegistrationStatus::kTooFewCorrespondences;
      break;
    }
    const double rejection_mm = rejection_distance_mm(candidates, parameters);
    inliers.clear();
    double sum_squares = 0.0;
    std::fill(is_inlier.begin(), is_inlier.end(), 0);
    for (const Correspondence& c : candidates) {
      const auto i = static_cast<std::size_t>(c.scene_index);
      if (std::abs(c.distance_mm) > rejection_mm * (was_inlier[i] ? kInlierHysteresis : 1.0))
        continue;
      is_inlier[i] = 1;
      inliers.push_back(c);
      sum_squares += c.distance_mm * c.distance_mm;
    }
    if (static_cast<int>(inliers.size()) < parameters.min_inliers) {
      result.status = RegistrationStatus::kTooFewCorrespondences;
      break;
    }
    was_inlier.swap(is_inlier);
    result.iterations = iteration;
    result.inliers = static_cast<int>(inliers.size());
    result.inlier_fraction = static_cast<double>(inliers.size()) / scene.size();
    result.rms_residual_mm = std::sqrt(sum_squares / static_cast<double>(inliers.size()));

    belt_rows.clear();
    if (belt.holds()) {
      double inlier_weight = 0.0;
      for (const Correspondence& c : inliers) inlier_weight += c.weight;
      for_each_belt_row(belt, result.T_model_scene, [&](const BeltRow& row, double share) {
        belt_rows.push_back(
            {-1, row.point_mm, row.normal, row.height_mm, share * belt.weight * inlier_weight});
      });
    }
    Increment increment;
    const SolveStatus solved = solve_increment(inliers, belt_rows, increment);
    planar = solved == SolveStatus::kPlanar;
    result.weakest_motion = increment.weakest_motion;
    result.weakest_lever_mm = increment.lever_mm;
    result.weakest_constraint = increment.weakest_constraint;
    result.twist_centre_mm = increment.centroid_mm;
    if (solved == SolveStatus::kUnconstrained) {
      result.status = RegistrationStatus::kDegenerate;
      break;
    }
    // Step (iii) of §6.4: T^k = T T^{k-1}.
    const RigidTransform T_before_last = T_last;
    T_last = result.T_model_scene;
    result.T_model_scene = (increment.T_new_old * result.T_model_scene).normalized();
    if (increment.rotation_rad < parameters.convergence_rotation_rad &&
        increment.centroid_shift_mm < parameters.convergence_translation_mm) {
      result.status = RegistrationStatus::kConverged;
      break;
    }
    // A control point whose normal line lands on the edge of the model's data can be
    // matched in one pass and not in the next, flipping T between two nearby transforms for
    // ever. Back where it was two passes ago within the tolerances: converged, since the
    // iterate now only oscillates by less than the tolerances.
    if (iteration > 2 &&
        rotation_angle_between_rad(result.T_model_scene.rotation, T_before_last.rotation) <
            parameters.convergence_rotation_rad &&
        (result.T_model_scene.apply(scene_centroid_mm) - T_before_last.apply(scene_centroid_mm))
                .norm() < parameters.convergence_translation_mm) {
      result.status = RegistrationStatus::kConverged;
      break;
    }
  }
  // Still planar at the end: the pose is the last iterate, but three of its parameters are
  // whatever the start made them.
  if (planar && result.status != RegistrationStatus::kTooFewCorrespondences)
    result.status = RegistrationStatus::kDegenerate;
  result.converged = result.status == RegistrationStatus::kConverged;
  return result;
}

AlignmentScore score_alignment(const RegistrationPoints& scene, const RegistrationPoints& model,
                               const RigidTransform& T_model_scene,
                               const RegistrationParameters& parameters, const TaskRunner& tasks) {
  AlignmentScore score;
  if (!valid_input(scene, model, parameters)) return score;
  RegistrationParameters unweighted = parameters;
  unweighted.estimator = RegistrationEstimator::kChenMedioni;
  std::vector<Correspondence> candidates;
  find_correspondences(scene, model, T_model_scene, unweighted, candidates, tasks);
  const double limit2 =
      parameters.max_correspondence_distance_mm * parameters.max_correspondence_distance_mm;
  double sum = limit2 * static_cast<double>(scene.size() - static_cast<int>(candidates.size()));
  int matched = 0;
  for (const Correspondence& c : candidates) {
    const double d2 = c.distance_mm * c.distance_mm;
    sum += std::min(d2, limit2);
    matched += d2 <= limit2 ? 1 : 0;
  }
  score.truncated_mean_square_mm2 = sum / scene.size();
  score.matched_fraction = static_cast<double>(matched) / scene.size();
  return score;
}

void correspondence_distances(const RegistrationPoints& scene, const RegistrationPoints& model,
                              const RigidTransform& T_model_scene,
                              const RegistrationParameters& parameters,
                              std::vector<double>& abs_distance_mm, const TaskRunner& tasks) {
  abs_distance_mm.assign(static_cast<std::size_t>(scene.size()),
                         std::numeric_limits<double>::infinity());
  if (!valid_input(scene, model, parameters)) return;
  RegistrationParameters unweighted = parameters;
  unweighted.estimator = RegistrationEstimator::kChenMedioni;
  std::vector<Correspondence> candidates;
  find_correspondences(scene, model, T_model_scene, unweighted, candidates, tasks);
  for (const Correspondence& c : candidates)
    abs_distance_mm[static_cast<std::size_t>(c.scene_index)] = std::abs(c.distance_mm);
}

}  // namespace cosmos
