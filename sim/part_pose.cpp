#include "sim/part_pose.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "sim/convex_hull.hpp"
#include "sim/seeded_random.hpp"
#include "sim/view_sphere.hpp"

namespace cosmos {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr std::uint64_t kFaceStream = 0xFACE;
constexpr std::uint64_t kYawStream = 0x7A3;

Eigen::Matrix3d yaw(double angle_rad) {
  return Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// Divergence theorem over the triangles: signed volume and first moment. The sign follows the
// winding; their ratio does not depend on it.
void volume_moments(const TriangleMesh& mesh, double& volume, Eigen::Vector3d& moment) {
  volume = 0.0;
  moment.setZero();
  for (const Eigen::Vector3i& triangle : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[static_cast<std::size_t>(triangle[0])].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[static_cast<std::size_t>(triangle[1])].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[static_cast<std::size_t>(triangle[2])].cast<double>();
    const double v = a.dot(b.cross(c)) / 6.0;
    volume += v;
    moment += v * (a + b + c) / 4.0;
  }
}

bool inside_hull(const ConvexHull& hull, const Eigen::Vector3d& point) {
  for (const HullFace& face : hull.faces) {
    if (face.normal.dot(point) + face.offset > 0.0) return false;
  }
  return true;
}

Eigen::Vector3d centre_of_mass(const TriangleMesh& mesh, const ConvexHull& hull) {
  double volume = 0.0;
  Eigen::Vector3d moment;
  volume_moments(mesh, volume, moment);
  if (std::abs(volume) >= 0.01 * hull.volume) {
    const Eigen::Vector3d centroid = moment / volume;
    if (inside_hull(hull, centroid)) return centroid;
  }
  return hull.centroid;
}

// The rotation laying a flat mesh on its plane: its direction of least spread becomes z.
Eigen::Matrix3d flat_rotation(const TriangleMesh& mesh) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3f& v : mesh.vertices) mean += v.cast<double>();
  mean /= static_cast<double>(mesh.vertices.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3f& v : mesh.vertices) {
    const Eigen::Vector3d d = v.cast<double>() - mean;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  return rotation_looking_along(solver.eigenvectors().col(0));
}

// Per hull face: the solid angle it subtends at the centre of mass when the centre projects
// inside it (a face the part can rest on), else 0.
std::vector<double> stable_face_weights(const TriangleMesh& mesh, const ConvexHull& hull) {
  const Eigen::Vector3d centre = centre_of_mass(mesh, hull);
  std::vector<double> weight(hull.faces.size(), 0.0);
  for (std::size_t f = 0; f < hull.faces.size(); ++f)
    if (projects_inside(hull.faces[f], centre)) weight[f] = solid_angle(hull.faces[f], centre);
  return weight;
}

std::size_t face_nearest_centre(const TriangleMesh& mesh, const ConvexHull& hull) {
  const Eigen::Vector3d centre = centre_of_mass(mesh, hull);
  std::size_t chosen = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < hull.faces.size(); ++f) {
    const double distance = -(hull.faces[f].normal.dot(centre) + hull.faces[f].offset);
    if (distance < nearest) {
      nearest = distance;
      chosen = f;
    }
  }
  return chosen;
}

}  // namespace

Eigen::Matrix3d rotation_from_xyz_deg(double rx_deg, double ry_deg, double rz_deg) {
  return (Eigen::AngleAxisd(rz_deg * kDegree, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(ry_deg * kDegree, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rx_deg * kDegree, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Matrix3d random_rotation(std::uint64_t seed) {
  SeededRandom random(seed);
  const double u1 = random.uniform();
  const double u2 = random.uniform();
  const double u3 = random.uniform();
  const double a = std::sqrt(1.0 - u1);
  const double b = std::sqrt(u1);
  const double two_pi = 2.0 * std::numbers::pi;
  const Eigen::Quaterniond q(b * std::cos(two_pi * u3), a * std::sin(two_pi * u2),
                             a * std::cos(two_pi * u2), b * std::sin(two_pi * u3));
  return q.normalized().toRotationMatrix();
}

Eigen::Vector3d centre_of_mass(const TriangleMesh& mesh) {
  try {
    return centre_of_mass(mesh, convex_hull(mesh.vertices));
  } catch (const std::invalid_argument&) {
    // A flat mesh: the vertex mean lies in its plane.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3f& v : mesh.vertices) mean += v.cast<double>();
    return mesh.vertices.empty()
               ? mean
               : Eigen::Vector3d(mean / static_cast<double>(mesh.vertices.size()));
  }
}

Eigen::Matrix3d resting_rotation(const TriangleMesh& mesh, std::uint64_t seed) {
  SeededRandom yaw_random(mix_seed(seed, kYawStream));
  const double yaw_rad = 2.0 * std::numbers::pi * yaw_random.uniform();
  ConvexHull hull;
  try {
    hull = convex_hull(mesh.vertices);
  } catch (const std::invalid_argument&) {
    return yaw(yaw_rad) * flat_rotation(mesh);
  }
  const std::vector<double> weight = stable_face_weights(mesh, hull);
  double total = 0.0;
  for (double w : weight) total += w;
  // A convex solid always has a stable face; only rounding on a degenerate hull can leave
  // none, and then the face nearest the centre (the most stable one) is used.
  std::size_t chosen = 0;
  if (total > 0.0) {
    SeededRandom face_random(mix_seed(seed, kFaceStream));
    double pick = face_random.uniform() * total;
    chosen = hull.faces.size() - 1;
    for (std::size_t f = 0; f < hull.faces.size(); ++f) {
      if (weight[f] > 0.0 && pick < weight[f]) {
        chosen = f;
        break;
      }
      pick -= weight[f];
    }
    while (weight[chosen] <= 0.0) --chosen;
  } else {
    chosen = face_nearest_centre(mesh, hull);
  }
  // The face's outward normal must point down the belt: R · normal = −z.
  return yaw(yaw_rad) * rotation_looking_along(-hull.faces[chosen].normal);
}

std::vector<StableRestingPose> stable_resting_poses(const TriangleMesh& mesh,
                                                    const RestingPoseParameters& parameters) {
  std::vector<StableRestingPose> poses;
  if (mesh.vertices.empty()) return poses;
  const auto height_mm = [&mesh](const Eigen::Matrix3d& R_belt_part) {
    double lowest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3f& v : mesh.vertices)
      lowest = std::min(lowest, (R_belt_part * v.cast<double>()).z());
    return -lowest;
  };
  ConvexHull hull;
  try {
    hull = convex_hull(mesh.vertices);
  } catch (const std::invalid_argument&) {
    const Eigen::Matrix3d R = flat_rotation(mesh);
    poses.push_back({R, height_mm(R), 1.0});
    return poses;
  }
  std::vector<double> weight = stable_face_weights(mesh, hull);
  double total = 0.0;
  for (double w : weight) total += w;
  if (total <= 0.0) {
    weight.assign(hull.faces.size(), 0.0);
    weight[face_nearest_centre(mesh, hull)] = total = 1.0;
  }
  std::vector<std::size_t> order(hull.faces.size());
  for (std::size_t f = 0; f < order.size(); ++f) order[f] = f;
  std::stable_sort(order.begin(), order.end(),
                   [&weight](std::size_t a, std::size_t b) { return weight[a] > weight[b]; });
  const double merge_cos = std::cos(parameters.merge_deg * kDegree);
  std::vector<Eigen::Vector3d> normals;
  for (std::size_t f : order) {
    if (weight[f] <= 0.0) break;
    const Eigen::Vector3d& normal = hull.faces[f].normal;
    std::size_t merged = 0;
    while (merged < normals.size() && normals[merged].dot(normal) < merge_cos) ++merged;
    if (merged < normals.size()) {
      poses[merged].probability += weight[f] / total;
      continue;
    }
    const Eigen::Matrix3d R = rotation_looking_along(-normal);
    normals.push_back(normal);
    poses.push_back({R, height_mm(R), weight[f] / total});
  }
  std::stable_sort(poses.begin(), poses.end(),
                   [](const StableRestingPose& a, const StableRestingPose& b) {
                     return a.probability > b.probability;
                   });
  std::erase_if(poses, [&parameters](const StableRestingPose& pose) {
    return pose.probability < parameters.min_probability;
  });
  if (poses.size() > static_cast<std::size_t>(parameters.max_poses))
    poses.resize(static_cast<std::size_t>(parameters.max_poses));
  return poses;
}

std::vector<Eigen::Vector3d> hull_vertices(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> corners;
  try {
    for (const HullFace& face : convex_hull(mesh.vertices).faces)
      corners.insert(corners.end(), face.corners.begin(), face.corners.end());
  } catch (const std::invalid_argument&) {
    for (const Eigen::Vector3f& v : mesh.vertices) corners.push_back(v.cast<double>());
  }
  const auto lexicographic = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(corners.begin(), corners.end(), lexicographic);
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  return corners;
}

Eigen::Isometry3d place_on_belt(const TriangleMesh& mesh, const Eigen::Matrix3d& R_belt_part,
                                double x_mm, double y_mm) {
  if (mesh.vertices.empty()) throw std::invalid_argument("place_on_belt: empty mesh");
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3f& v : mesh.vertices) box.extend(R_belt_part * v.cast<double>());
  Eigen::Isometry3d T_belt_part = Eigen::Isometry3d::Identity();
  T_belt_part.linear() = R_belt_part;
  T_belt_part.translation() =
      Eigen::Vector3d(x_mm - box.center().x(), y_mm - box.center().y(), -box.min().z());
  return T_belt_part;
}

}  // namespace cosmos
