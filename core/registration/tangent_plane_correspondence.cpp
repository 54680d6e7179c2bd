#include "core/registration/tangent_plane_correspondence.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {
namespace {

// A line meeting the tangent plane at more than ~78 degrees from its normal is too
// tangential for its intersection to locate anything.
constexpr double kMinLineCosine = 0.2;
// The foot has settled when it moves less than this fraction of a grid cell.
constexpr double kSettledCellFraction = 1e-3;

struct BlendedPlane {
  double height_mm = 0.0;
  double a = 0.0;
  double b = 0.0;
  int nearest = -1;
};

// The four cells around (x, y) must all be control points: near holes and borders the
// blend would extrapolate. Each cell's local fit is evaluated (height and slopes) at the
// query, then blended with bilinear weights.
// `cells_per_mm`: 1 / the grid spacings (the caller divides once, not at every step).
bool blend_planes(const RegistrationPoints& model, const Eigen::Vector2d& cells_per_mm, double x_mm,
                  double y_mm, BlendedPlane& out) {
  const double u = (x_mm - model.origin_x_mm) * cells_per_mm.x();
  const double v = (y_mm - model.origin_y_mm) * cells_per_mm.y();
  if (!(u >= 0.0 && v >= 0.0 && u < model.grid_width - 1 && v < model.grid_height - 1))
    return false;
  const int u0 = static_cast<int>(u), v0 = static_cast<int>(v);
  const double fu = u - u0, fv = v - v0;
  const int index[4] = {model.point_at_cell(u0, v0), model.point_at_cell(u0 + 1, v0),
                        model.point_at_cell(u0, v0 + 1), model.point_at_cell(u0 + 1, v0 + 1)};
  const double weight[4] = {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv};
  out = BlendedPlane{};
  double best_weight = -1.0;
  for (int k = 0; k < 4; ++k) {
    if (index[k] < 0) return false;
    const auto s = model.surface.col(index[k]);
    const double dx = x_mm - model.position_mm(0, index[k]);
    const double dy = y_mm - model.position_mm(1, index[k]);
    out.height_mm += weight[k] * surface_basis(dx, dy).dot(s);
    out.a += weight[k] * (s(kSlopeX) + 2 * s(kCurveXX) * dx + s(kCurveXY) * dy);
    out.b += weight[k] * (s(kSlopeY) + s(kCurveXY) * dx + 2 * s(kCurveYY) * dy);
    if (weight[k] > best_weight) {
      best_weight = weight[k];
      out.nearest = index[k];
    }
  }
  return true;
}

}  // namespace

CorrespondenceStatus find_tangent_plane(const RegistrationPoints& model,
                                        const Eigen::Vector3d& point_mm,
                                        const Eigen::Vector3d& line_direction, int max_steps,
                                        TangentPlaneCorrespondence& out) {
  // The loop compares squared lengths: the one square root waits until the foot has settled.
  const double settled_mm = kSettledCellFraction * std::min(model.spacing_x_mm, model.spacing_y_mm);
  const double settled2 = settled_mm * settled_mm;
  const double min_approach2 = kMinLineCosine * kMinLineCosine * line_direction.squaredNorm();
  Eigen::Vector2d foot = point_mm.head<2>();
  const Eigen::Vector2d cells_per_mm(1.0 / model.spacing_x_mm, 1.0 / model.spacing_y_mm);
  out.steps = 0;
  while (out.steps < max_steps) {
    BlendedPlane plane;
    if (!blend_planes(model, cells_per_mm, foot.x(), foot.y(), plane))
      return CorrespondenceStatus::kOffModel;
    ++out.steps;
    const double norm2 = 1.0 + plane.a * plane.a + plane.b * plane.b;
    // (-a, -b, 1) . direction: the line's approach to the plane, unnormalized.
    const double approach =
        line_direction.z() - plane.a * line_direction.x() - plane.b * line_direction.y();
    if (approach * approach < min_approach2 * norm2) return CorrespondenceStatus::kGrazing;
    // Line p + s d meets the plane z = h + a (x - foot_x) + b (y - foot_y).
    const double s = (plane.height_mm + plane.a * (point_mm.x() - foot.x()) +
                      plane.b * (point_mm.y() - foot.y()) - point_mm.z()) /
                     approach;
    const Eigen::Vector2d next = point_mm.head<2>() + s * line_direction.head<2>();
    if ((next - foot).squaredNorm() < settled2) {
      const double norm = std::sqrt(norm2);
      out.model_point_mm = Eigen::Vector3d(foot.x(), foot.y(), plane.height_mm);
      out.model_slope = Eigen::Vector2d(plane.a, plane.b);
      out.model_normal = Eigen::Vector3d(-plane.a, -plane.b, 1.0) / norm;
      // Eq. 6.5 with the plane (A, B, C, D) = (n, -n . q); its sign there is the opposite,
      // which does not matter since only d_s^2 enters Eqs. 6.4 and 6.23.
      out.distance_mm = out.model_normal.dot(point_mm - out.model_point_mm);
      out.travel_mm = (point_mm - out.model_point_mm).norm();
      out.nearest_model_point = plane.nearest;
      return CorrespondenceStatus::kFound;
    }
    foot = next;
  }
  return CorrespondenceStatus::kNotConverged;
}

double distance_variance_mm2(const RegistrationPoints& model,
                             const TangentPlaneCorrespondence& correspondence,
                             const Eigen::Vector3d& point_mm, double scene_height_variance_mm2,
                             const Eigen::Vector3d& scene_view_axis) {
  const int k = correspondence.nearest_model_point;
  const double dx = point_mm.x() - model.position_mm(0, k);
  const double dy = point_mm.y() - model.position_mm(1, k);
  const double a = correspondence.model_slope.x(), b = correspondence.model_slope.y();
  const double norm2 = 1.0 + a * a + b * b;
  const double norm = std::sqrt(norm2);
  const double d = correspondence.distance_mm;
  // d_s = (z - h(dx, dy)) / sqrt(1 + h_x^2 + h_y^2), h the fit of model point k: its gradient
  // with respect to the fit's coefficients (Eq. 6.21's dd_s/dh).
  SurfaceVector slope_x_gradient, slope_y_gradient;
  slope_x_gradient << 0, 1, 0, 2 * dx, dy, 0;
  slope_y_gradient << 0, 0, 1, 0, dx, 2 * dy;
  const SurfaceVector gradient =
      -surface_basis(dx, dy) / norm - (d / norm2) * (a * slope_x_gradient + b * slope_y_gradient);
  const double model_sigma2 = model.z_noise_sigma_mm * model.z_noise_sigma_mm;
  const double fit_term = model_sigma2 * gradient.dot(model.fit_cofactor * gradient);
  // dd_s / dz_scene = n_q . (scene z axis): the orientation effect of §6.5.1.
  const double axis_cosine = correspondence.model_normal.dot(scene_view_axis);
  return fit_term + scene_height_variance_mm2 * axis_cosine * axis_cosine;
}

}  // namespace cosmos
