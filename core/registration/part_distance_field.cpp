#include "core/registration/part_distance_field.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/registration/occupied_cell_runs.hpp"

namespace cosmos {
namespace {

// Felzenszwalb & Huttenlocher's 1-D squared distance transform of the n samples f[i * step]
// (in place): the lower envelope of the parabolas (q - i)^2 + f(i).
void squared_distance_1d(float* f, int n, std::ptrdiff_t step, std::vector<float>& line,
                         std::vector<int>& apex, std::vector<double>& boundary) {
  for (int i = 0; i < n; ++i) line[static_cast<std::size_t>(i)] = f[i * step];
  int k = 0;
  apex[0] = 0;
  boundary[0] = -std::numeric_limits<double>::infinity();
  boundary[1] = std::numeric_limits<double>::infinity();
  const auto intersection = [&](int q, int p) {
    return ((line[static_cast<std::size_t>(q)] + static_cast<double>(q) * q) -
            (line[static_cast<std::size_t>(p)] + static_cast<double>(p) * p)) /
           (2.0 * (q - p));
  };
  for (int q = 1; q < n; ++q) {
    double s = intersection(q, apex[static_cast<std::size_t>(k)]);
    while (s <= boundary[static_cast<std::size_t>(k)]) {
      --k;
      s = intersection(q, apex[static_cast<std::size_t>(k)]);
    }
    ++k;
    apex[static_cast<std::size_t>(k)] = q;
    boundary[static_cast<std::size_t>(k)] = s;
    boundary[static_cast<std::size_t>(k) + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (boundary[static_cast<std::size_t>(k) + 1] < q) ++k;
    const int p = apex[static_cast<std::size_t>(k)];
    f[q * step] = static_cast<float>(static_cast<double>(q - p) * (q - p) +
                                     line[static_cast<std::size_t>(p)]);
  }
}

}  // namespace

PartDistanceField::PartDistanceField(const std::vector<Eigen::Vector3d>& points_part_mm,
                                     const PartDistanceFieldParameters& parameters)
    : PartDistanceField(part_surface_voxels(points_part_mm, parameters)) {}

PartDistanceField::PartDistanceField(const PartSurfaceVoxels& surface) {
  // The runs are decoded (and checked) below, once the grid is known to be bounded.
  if (surface.empty() || !part_surface_voxel_grid_bounded(surface)) return;
  std::copy(surface.size.begin(), surface.size.end(), size_);
  voxel_mm_ = surface.voxel_mm;
  voxels_per_mm_ = 1.0 / voxel_mm_;
  origin_mm_ = surface.origin_mm;
  const std::size_t voxels = static_cast<std::size_t>(size_[0]) * size_[1] * size_[2];
  // Far, in squared voxels: more than any distance in the grid, small enough to add to.
  const float far = 4.0f * static_cast<float>(size_[0] + size_[1] + size_[2]) *
                    static_cast<float>(size_[0] + size_[1] + size_[2]);
  std::vector<float> distance_mm(voxels, far);
  const auto voxel_index = [&](int x, int y, int z) {
    return (static_cast<std::size_t>(z) * size_[1] + y) * size_[0] + x;
  };
  const bool consistent = visit_occupied_cell_runs(
      surface.occupied_runs, voxels, surface.occupied_voxels,
      [&](std::size_t first, std::size_t end) {
        std::fill(distance_mm.begin() + static_cast<std::ptrdiff_t>(first),
                  distance_mm.begin() + static_cast<std::ptrdiff_t>(end), 0.0f);
      });
  if (!consistent) {
    *this = PartDistanceField();
    return;
  }
  const int longest = std::max({size_[0], size_[1], size_[2]});
  std::vector<float> line(static_cast<std::size_t>(longest));
  std::vector<int> apex(static_cast<std::size_t>(longest));
  std::vector<double> boundary(static_cast<std::size_t>(longest) + 1);
  const std::ptrdiff_t step_y = size_[0], step_z = static_cast<std::ptrdiff_t>(size_[0]) * size_[1];
  for (int z = 0; z < size_[2]; ++z)
    for (int y = 0; y < size_[1]; ++y)
      squared_distance_1d(&distance_mm[voxel_index(0, y, z)], size_[0], 1, line, apex, boundary);
  for (int z = 0; z < size_[2]; ++z)
    for (int x = 0; x < size_[0]; ++x)
      squared_distance_1d(&distance_mm[voxel_index(x, 0, z)], size_[1], step_y, line, apex,
                          boundary);
  for (int y = 0; y < size_[1]; ++y)
    for (int x = 0; x < size_[0]; ++x)
      squared_distance_1d(&distance_mm[voxel_index(x, y, 0)], size_[2], step_z, line, apex,
                          boundary);
  float largest = 0.0f;
  for (float& d : distance_mm) {
    d = std::sqrt(d) * static_cast<float>(voxel_mm_);
    largest = std::max(largest, d);
  }
  mm_per_unit_ = largest > 0 ? largest / 65535.0 : voxel_mm_;
  const double units_per_mm = 1.0 / mm_per_unit_;
  distance_units_.resize(voxels);
  for (std::size_t k = 0; k < voxels; ++k)
    distance_units_[k] = static_cast<std::uint16_t>(
        std::min(65535.0, std::round(static_cast<double>(distance_mm[k]) * units_per_mm)));
}

template <bool kGradient>
[[gnu::always_inline]] inline double PartDistanceField::sample(const Eigen::Vector3d& point_part_mm,
                                                               Eigen::Vector3d& gradient) const {
  if (kGradient) gradient.setZero();
  if (distance_units_.empty()) return std::numeric_limits<double>::infinity();
  // The hot loop of the pose search: one base index and fixed strides to the 8 corners, and
  // the way out of the grid only for points outside it. The upper clamp keeps the base a
  // corner below the last, so its +1 neighbours always exist (grids are >= 2 voxels wide).
  double u[3], f[3];
  int base[3];
  bool outside = false;
  for (int axis = 0; axis < 3; ++axis) {
    u[axis] = (point_part_mm[axis] - origin_mm_[axis]) * voxels_per_mm_;
    const double clamped = std::clamp(u[axis], 0.0, static_cast<double>(size_[axis] - 1) - 1e-9);
    outside |= clamped != u[axis];
    base[axis] = static_cast<int>(clamped);
    f[axis] = clamped - base[axis];
    u[axis] -= clamped;
  }
  const double outside_mm =
      outside ? std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * voxel_mm_ : 0.0;
  const std::ptrdiff_t step_y = size_[0];
  const std::ptrdiff_t step_z = static_cast<std::ptrdiff_t>(size_[0]) * size_[1];
  // Interpolated in the stored units, scaled once: the interpolant is linear in them.
  const std::uint16_t* c = distance_units_.data() + base[2] * step_z + base[1] * step_y + base[0];
  const double c000 = c[0], c100 = c[1], c010 = c[step_y], c110 = c[step_y + 1];
  const double c001 = c[step_z], c101 = c[step_z + 1], c011 = c[step_z + step_y],
               c111 = c[step_z + step_y + 1];
  const double fx = f[0], fy = f[1], fz = f[2];
  const double c00 = c000 + fx * (c100 - c000), c10 = c010 + fx * (c110 - c010);
  const double c01 = c001 + fx * (c101 - c001), c11 = c011 + fx * (c111 - c011);
  const double c0 = c00 + fy * (c10 - c00), c1 = c01 + fy * (c11 - c01);
  if (kGradient && !outside) {
    const double dx0 = (c100 - c000) + fy * ((c110 - c010) - (c100 - c000));
    const double dx1 = (c101 - c001) + fy * ((c111 - c011) - (c101 - c001));
    const double scale = voxels_per_mm_ * mm_per_unit_;
    gradient.x() = (dx0 + fz * (dx1 - dx0)) * scale;
    gradient.y() = ((c10 - c00) + fz * ((c11 - c01) - (c10 - c00))) * scale;
    gradient.z() = (c1 - c0) * scale;
  }
  return (c0 + fz * (c1 - c0)) * mm_per_unit_ + outside_mm;
}

double PartDistanceField::interpolate(const Eigen::Vector3d& point_part_mm,
                                      Eigen::Vector3d* gradient) const {
  Eigen::Vector3d unused;
  return gradient ? sample<true>(point_part_mm, *gradient) : sample<false>(point_part_mm, unused);
}

double field_truncated_mean_square_mm2(const RegistrationPoints& scene,
                                       const PartDistanceField& field,
                                       const RigidTransform& T_part_scene, double truncation_mm,
                                       double abandon_above_mm2) {
  if (scene.size() == 0) return truncation_mm * truncation_mm;
  const double limit2 = truncation_mm * truncation_mm;
  // The terms are never negative, so a partial sum past this bounds the mean from below (the
  // relative margin covers the rounding of the product and of the final division).
  const double abandon_sum = abandon_above_mm2 * scene.size() * (1 + 1e-9);
  Eigen::Vector3d unused;
  double sum = 0;
  for (int i = 0; i < scene.size(); ++i) {
    const double d = field.sample<false>(T_part_scene.apply(scene.position_mm.col(i)), unused);
    sum += std::min(d * d, limit2);
    if (sum > abandon_sum) return sum / (i + 1);
  }
  return sum / scene.size();
}

double field_fraction_within(const RegistrationPoints& scene, const PartDistanceField& field,
                             const RigidTransform& T_part_scene, double distance_mm) {
  if (scene.size() == 0) return 0;
  int within = 0;
  Eigen::Vector3d unused;
  for (int i = 0; i < scene.size(); ++i)
    within +=
        field.sample<false>(T_part_scene.apply(scene.position_mm.col(i)), unused) <= distance_mm;
  return static_cast<double>(within) / scene.size();
}

RigidTransform align_in_distance_field(const RegistrationPoints& scene,
                                       const PartDistanceField& field,
                                       const RigidTransform& T_part_scene, int iterations,
                                       double truncation_mm, const BeltContact& belt) {
  RigidTransform T = T_part_scene;
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    Matrix6d normal = Matrix6d::Zero();
    Vector6d right = Vector6d::Zero();
    int used = 0;
    for (int i = 0; i < scene.size(); ++i) {
      const Eigen::Vector3d q = T.apply(scene.position_mm.col(i));
      Eigen::Vector3d gradient;
      const double d = field.sample<true>(q, gradient);
      if (!(d < truncation_mm) || gradient.squaredNorm() < 1e-6) continue;
      // d(q + omega x q + t) ~ d + g . t + (q x g) . omega
      const Eigen::Vector3d moment = q.cross(gradient);
      Vector6d jacobian;
      jacobian << moment.x(), moment.y(), moment.z(), gradient.x(), gradient.y(), gradient.z();
      // The full outer product: fixed-size and inlined, it is cheaper than rankUpdate's call.
      normal.noalias() += jacobian * jacobian.transpose();
      right -= jacobian * d;
      ++used;
    }
    if (used < 6) break;
    if (belt.holds())
      for_each_belt_row(belt, T, [&](const BeltRow& row, double share) {
        const Eigen::Vector3d moment = row.point_mm.cross(row.normal);
        Vector6d jacobian;
        jacobian << moment.x(), moment.y(), moment.z(), row.normal.x(), row.normal.y(),
            row.normal.z();
        const double weight = share * belt.weight * used;
        normal.noalias() += weight * jacobian * jacobian.transpose();
        right -= weight * jacobian * row.height_mm;
      });
    // A little damping keeps the directions the points do not constrain where they are.
    normal.diagonal().array() += 1e-6 * normal.diagonal().maxCoeff() + 1e-9;
    const Vector6d step = normal.selfadjointView<Eigen::Lower>().ldlt().solve(right);
    if (!step.allFinite()) break;
    T = (transform_from_increment(step.head<3>(), step.tail<3>()) * T).normalized();
  }
  return T;
}

}  // namespace cosmos
