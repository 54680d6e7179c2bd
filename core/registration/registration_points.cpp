#include "core/registration/registration_points.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cosmos {
namespace {

// Registration estimates 6 parameters (Eq. 6.2).
constexpr int kMinPoints = 6;

using WindowFit = Eigen::Matrix<double, kSurfaceCoefficients, Eigen::Dynamic>;

bool valid_parameters(const RangeImage& image, const RegistrationPointParameters& p,
                      const DarbouxFrameField* frames) {
  if (p.stride_px < 1 || p.window_size < 3 || p.window_size % 2 == 0) return false;
  if (!(p.depth_jump_mm > 0) || !(p.max_residual_noise_ratio > 0)) return false;
  if (!(p.max_tilt_deg > 0 && p.max_tilt_deg < 90) || !(p.z_noise_sigma_mm >= 0)) return false;
  if (!(image.pixel_size_x_mm > 0) || !(image.pixel_size_y_mm > 0)) return false;
  if (frames && (frames->width() != image.width() || frames->height() != image.height()))
    return false;
  return image.width() > 0 && image.height() > 0;
}

// Whole window inside the image, every sample present, no 4-neighbour step above the jump
// threshold: the window lies on one smooth surface (§6.7.1, away from jumps and holes).
bool window_on_one_surface(const RangeImage& image, int column, int row, int half,
                           double depth_jump_mm) {
  if (column < half || row < half || column + half >= image.width() || row + half >= image.height())
    return false;
  for (int r = row - half; r <= row + half; ++r) {
    const float* z = image.z_mm.row(r);
    const float* z_next = r < row + half ? image.z_mm.row(r + 1) : nullptr;
    for (int c = column - half; c <= column + half; ++c) {
      if (!std::isfinite(z[c])) return false;
      if (c < column + half && std::abs(z[c + 1] - z[c]) > depth_jump_mm) return false;
      if (z_next && std::abs(z_next[c] - z[c]) > depth_jump_mm) return false;
    }
  }
  return true;
}

// The design matrix of the full window (Eq. 6.7, rows (1, dx, dy[, dx^2, dx dy, dy^2])),
// samples in row-major window order.
struct WindowDesign {
  Eigen::MatrixXd A;     // n x used coefficients
  WindowFit projection;  // coefficients = projection * z (unused rows 0)
  Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients> cofactor;
  int used = 0;
};

WindowDesign window_design(const RangeImage& image, int half, bool quadric) {
  WindowDesign design;
  design.used = quadric ? kSurfaceCoefficients : 3;
  const int side = 2 * half + 1;
  design.A.resize(side * side, design.used);
  for (int dr = -half, k = 0; dr <= half; ++dr)
    for (int dc = -half; dc <= half; ++dc, ++k)
      design.A.row(k) = surface_basis(dc * image.pixel_size_x_mm, dr * image.pixel_size_y_mm)
                            .head(design.used)
                            .transpose();
  const Eigen::MatrixXd cofactor = (design.A.transpose() * design.A).inverse();
  design.cofactor.setZero();
  design.cofactor.topLeftCorner(design.used, design.used) = cofactor;
  design.projection = WindowFit::Zero(kSurfaceCoefficients, side * side);
  design.projection.topRows(design.used) = cofactor * design.A.transpose();
  return design;
}

struct Candidate {
  int cell, column, row;
  SurfaceVector surface;
  double residual_rms_mm;
};

double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

RegistrationPointsResult build_registration_points(const RangeImage& image,
                                                   const RegistrationPointParameters& parameters,
                                                   const DarbouxFrameField* frames) {
  RegistrationPointsResult result;
  if (!valid_parameters(image, parameters, frames)) {
    result.status = RegistrationPointsStatus::kInvalidParameters;
    return result;
  }
  const int half = parameters.window_size / 2;
  const int side = 2 * half + 1;
  const int stride = parameters.stride_px;
  const WindowDesign design = window_design(image, half, parameters.quadric_fit);

  RegistrationPoints& points = result.points;
  points.grid_width = (image.width() + stride - 1) / stride;
  points.grid_height = (image.height() + stride - 1) / stride;
  points.origin_x_mm = image.origin_x_mm;
  points.origin_y_mm = image.origin_y_mm;
  points.spacing_x_mm = stride * image.pixel_size_x_mm;
  points.spacing_y_mm = stride * image.pixel_size_y_mm;
  points.cell_point.assign(static_cast<std::size_t>(points.grid_width) * points.grid_height, -1);
  points.fit_cofactor = design.cofactor;

  std::vector<Candidate> candidates;
  std::vector<double> residuals;
  Eigen::VectorXd window(side * side);
  for (int v = 0; v < points.grid_height; ++v) {
    for (int u = 0; u < points.grid_width; ++u) {
      const int column = u * stride, row = v * stride;
      if (!window_on_one_surface(image, column, row, half, parameters.depth_jump_mm)) continue;
      for (int dr = -half, k = 0; dr <= half; ++dr)
        for (int dc = -half; dc <= half; ++dc, ++k) window(k) = image.z_mm(column + dc, row + dr);
      const SurfaceVector surface = design.projection * window;
      const double rss = (window - design.A * surface.head(design.used)).squaredNorm();
      const double residual = std::sqrt(rss / (side * side - design.used));
      candidates.push_back({v * points.grid_width + u, column, row, surface, residual});
      residuals.push_back(residual);
    }
  }
  if (candidates.size() < static_cast<std::size_t>(kMinPoints)) {
    result.status = RegistrationPointsStatus::kTooFewPoints;
    return result;
  }
  // The median residual is robust to the rough windows and creases the smoothness test is
  // there to remove.
  points.z_noise_sigma_mm =
      parameters.z_noise_sigma_mm > 0 ? parameters.z_noise_sigma_mm : median(residuals);
  const double max_residual_mm = parameters.max_residual_noise_ratio * points.z_noise_sigma_mm;
  const double min_normal_z = std::cos(parameters.max_tilt_deg * std::numbers::pi / 180.0);

  std::vector<const Candidate*> kept;
  std::vector<Eigen::Vector3d> normals;
  for (const Candidate& c : candidates) {
    if (c.residual_rms_mm > max_residual_mm) continue;
    Eigen::Vector3d normal =
        Eigen::Vector3d(-c.surface(kSlopeX), -c.surface(kSlopeY), 1.0).normalized();
    if (frames && frames->valid(c.column, c.row)) {
      const std::size_t pixel = frames->valid.index(c.column, c.row);
      normal = Eigen::Vector3d(frames->frame[kNx][pixel], frames->frame[kNy][pixel],
                               frames->frame[kNz][pixel])
                   .normalized();
    }
    if (normal.z() < min_normal_z) continue;
    kept.push_back(&c);
    normals.push_back(normal);
  }
  const int n = static_cast<int>(kept.size());
  points.position_mm.resize(3, n);
  points.normal.resize(3, n);
  points.surface.resize(kSurfaceCoefficients, n);
  points.residual_rms_mm.resize(n);
  for (int i = 0; i < n; ++i) {
    const Candidate& c = *kept[static_cast<std::size_t>(i)];
    points.cell_point[static_cast<std::size_t>(c.cell)] = i;
    points.position_mm.col(i) << image.x_mm(c.column), image.y_mm(c.row), c.surface(kHeight);
    points.normal.col(i) = normals[static_cast<std::size_t>(i)];
    points.surface.col(i) = c.surface;
    points.residual_rms_mm(i) = c.residual_rms_mm;
  }
  if (n < kMinPoints) result.status = RegistrationPointsStatus::kTooFewPoints;
  return result;
}

RegistrationPoints select_points(const RegistrationPoints& points,
                                 const std::vector<int>& indices) {
  RegistrationPoints subset;
  subset.fit_cofactor = points.fit_cofactor;
  subset.z_noise_sigma_mm = points.z_noise_sigma_mm;
  const auto count = static_cast<Eigen::Index>(indices.size());
  subset.position_mm.resize(3, count);
  subset.normal.resize(3, count);
  subset.surface.resize(kSurfaceCoefficients, count);
  subset.residual_rms_mm.resize(count);
  for (Eigen::Index k = 0; k < count; ++k) {
    const int i = indices[static_cast<std::size_t>(k)];
    subset.position_mm.col(k) = points.position_mm.col(i);
    subset.normal.col(k) = points.normal.col(i);
    subset.surface.col(k) = points.surface.col(i);
    subset.residual_rms_mm(k) = points.residual_rms_mm(i);
  }
  return subset;
}

std::vector<int> spread_indices(int size, int count) {
  const int step = std::max(1, size / std::max(count, 1));
  std::vector<int> indices;
  for (int i = 0; i < size; i += step) indices.push_back(i);
  return indices;
}

RegistrationPoints spread_subset(const RegistrationPoints& points, int count) {
  return select_points(points, spread_indices(points.size(), count));
}

std::vector<int> farthest_point_indices(const RegistrationPoints& points, int count) {
  const int size = points.size();
  std::vector<int> chosen;
  if (size <= count) {
    for (int i = 0; i < size; ++i) chosen.push_back(i);
    return chosen;
  }
  if (count <= 0) return chosen;
  const auto farthest_from = [&](const auto& squared_distance) {
    int farthest = 0;
    double farthest_mm2 = -1;
    for (int i = 0; i < size; ++i)
      if (const double d = squared_distance(i); d > farthest_mm2) {
        farthest = i;
        farthest_mm2 = d;
      }
    return farthest;
  };
  const Eigen::Vector3d centroid = points.position_mm.rowwise().mean();
  chosen.push_back(
      farthest_from([&](int i) { return (points.position_mm.col(i) - centroid).squaredNorm(); }));
  std::vector<double> nearest_chosen_mm2(static_cast<std::size_t>(size),
                                         std::numeric_limits<double>::infinity());
  while (static_cast<int>(chosen.size()) < count) {
    const Eigen::Vector3d last = points.position_mm.col(chosen.back());
    chosen.push_back(farthest_from([&](int i) {
      double& nearest = nearest_chosen_mm2[static_cast<std::size_t>(i)];
      nearest = std::min(nearest, (points.position_mm.col(i) - last).squaredNorm());
      return nearest;
    }));
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

}  // namespace cosmos
