#include "sim/analytic_surface.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <utility>

#include "core/input_error.hpp"
#include "sim/analytic_shapes.hpp"

namespace cosmos {
namespace {

constexpr std::pair<const char*, AnalyticShape> kShapeNames[] = {
    {"sphere", AnalyticShape::kSphere},        {"cup", AnalyticShape::kCup},
    {"cylinder", AnalyticShape::kCylinder},    {"saddle", AnalyticShape::kSaddle},
    {"plane", AnalyticShape::kPlane},          {"torus", AnalyticShape::kTorus},
    {"ellipsoid", AnalyticShape::kEllipsoid},  {"capsule", AnalyticShape::kCapsule},
    {"box-corner", AnalyticShape::kBoxCorner},
};

// Bounds the memory of one surface (the truth grid costs ~40 bytes per pixel).
constexpr double kMaxPixels = 16777216.0;

std::string number_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

double value_or(const std::optional<double>& value, double fallback) {
  return value ? *value : fallback;
}

class FieldCheck {
 public:
  explicit FieldCheck(AnalyticShape shape)
      : prefix_("analytic " + analytic_shape_name(shape) + ": ") {}
  void positive(const char* field, double value) const {
    if (!(std::isfinite(value) && value > 0.0)) fail(field, value, "must be positive and finite");
  }
  void non_negative(const char* field, double value) const {
    if (!(std::isfinite(value) && value >= 0.0)) fail(field, value, "must be >= 0 and finite");
  }
  void finite(const char* field, double value) const {
    if (!std::isfinite(value)) fail(field, value, "must be finite");
  }
  [[noreturn]] void fail(const char* field, double value, const std::string& reason) const {
    throw InputError(prefix_ + field + " = " + number_text(value) + ": " + reason);
  }

 private:
  std::string prefix_;
};

// Normal deviates by the Box-Muller transform of 53-bit uniforms from mt19937_64: unlike
// std::normal_distribution its output is specified, so a seed gives the same noise with every
// standard library.
class SeededNormal {
 public:
  explicit SeededNormal(std::uint64_t seed) : engine_(seed) {}
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: the logarithm stays finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(2.0 * std::numbers::pi * u2);
    has_spare_ = true;
    return radius * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// Eq. 3.2 in the convex-positive convention (see AnalyticTruth).
double shape_index_of(double kappa1, double kappa2) {
  if (kappa1 == 0.0 && kappa2 == 0.0) return 2.0;
  if (kappa1 == kappa2) return kappa1 > 0.0 ? 1.0 : 0.0;
  return 0.5 + std::atan((kappa1 + kappa2) / (kappa1 - kappa2)) / std::numbers::pi;
}

Eigen::Matrix3d turn_about_z(double rotate_deg) {
  const double angle_rad = rotate_deg * std::numbers::pi / 180.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  rotation(0, 0) = std::cos(angle_rad);
  rotation(0, 1) = 0.0 - std::sin(angle_rad);  // not -sin: no "-0" in the sidecar at 0 deg
  rotation(1, 0) = std::sin(angle_rad);
  rotation(1, 1) = std::cos(angle_rad);
  return rotation;
}

}  // namespace

AnalyticShape parse_analytic_shape(std::string_view name) {
  if (name == "box_corner") return AnalyticShape::kBoxCorner;
  for (const auto& [text, shape] : kShapeNames) {
    if (name == text) return shape;
  }
  throw InputError("unknown shape '" + std::string(name) + "' (valid: " + analytic_shape_names() +
                   ")");
}

std::string analytic_shape_name(AnalyticShape shape) {
  for (const auto& [text, candidate] : kShapeNames) {
    if (candidate == shape) return text;
  }
  return "unknown";
}

std::string analytic_shape_names() {
  std::string names;
  for (const auto& [text, shape] : kShapeNames)
    names += (names.empty() ? "" : ", ") + std::string(text);
  return names;
}

AnalyticDimensions resolve_dimensions(const AnalyticSurfaceSpec& spec) {
  const FieldCheck check(spec.shape);
  check.positive("radius_mm", spec.radius_mm);
  check.positive("pixel_size_mm", spec.pixel_size_mm);
  check.non_negative("noise_mm", spec.noise_mm);
  check.finite("rotate_deg", spec.rotate_deg);
  if (spec.margin_px < 0) check.fail("margin_px", spec.margin_px, "must be >= 0");

  const double r = spec.radius_mm;
  AnalyticDimensions d;
  d.radius_mm = r;
  d.cylinder_length_mm = value_or(spec.cylinder_length_mm, 3.2 * r);
  d.saddle_half_width_mm = value_or(spec.saddle_half_width_mm, 0.8 * r);
  d.plane_half_width_mm = value_or(spec.plane_half_width_mm, r);
  d.plane_tilt_deg = value_or(spec.plane_tilt_deg, 20.0);
  d.torus_major_radius_mm = value_or(spec.torus_major_radius_mm, 1.2 * r);
  d.torus_minor_radius_mm = value_or(spec.torus_minor_radius_mm, 0.48 * r);
  d.ellipsoid_semi_axes_mm =
      spec.ellipsoid_semi_axes_mm.value_or(Eigen::Vector3d(1.2, 0.8, 0.6) * r);
  d.capsule_radius_mm = value_or(spec.capsule_radius_mm, 0.6 * r);
  d.capsule_length_mm = value_or(spec.capsule_length_mm, 1.6 * r);
  d.box_edge_mm = value_or(spec.box_edge_mm, 1.6 * r);

  check.positive("cylinder_length_mm", d.cylinder_length_mm);
  check.positive("saddle_half_width_mm", d.saddle_half_width_mm);
  check.positive("plane_half_width_mm", d.plane_half_width_mm);
  // Beyond 80 degrees the plane is grazing: no range sensor sees it.
  if (!(std::abs(d.plane_tilt_deg) <= 80.0)) {
    check.fail("plane_tilt_deg", d.plane_tilt_deg, "must lie in [-80, 80]");
  }
  check.positive("torus_major_radius_mm", d.torus_major_radius_mm);
  check.positive("torus_minor_radius_mm", d.torus_minor_radius_mm);
  if (d.torus_minor_radius_mm >= d.torus_major_radius_mm) {
    check.fail(
        "torus_minor_radius_mm", d.torus_minor_radius_mm,
        "must be below torus_major_radius_mm (" + number_text(d.torus_major_radius_mm) + ")");
  }
  check.positive("ellipsoid_semi_axes_mm.x", d.ellipsoid_semi_axes_mm.x());
  check.positive("ellipsoid_semi_axes_mm.y", d.ellipsoid_semi_axes_mm.y());
  check.positive("ellipsoid_semi_axes_mm.z", d.ellipsoid_semi_axes_mm.z());
  check.positive("capsule_radius_mm", d.capsule_radius_mm);
  check.positive("capsule_length_mm", d.capsule_length_mm);
  check.positive("box_edge_mm", d.box_edge_mm);
  return d;
}

AnalyticTruth analytic_truth_at(const AnalyticSurfaceSpec& spec,
                                const AnalyticDimensions& dimensions, double x_mm, double y_mm) {
  // The part turned by R about z shows at (x, y) the point the unturned part has at R^T (x, y).
  const Eigen::Matrix3d turn = turn_about_z(spec.rotate_deg);
  const Eigen::Vector3d local = turn.transpose() * Eigen::Vector3d(x_mm, y_mm, 0.0);
  const ShapePoint point = analytic_shape_point(spec.shape, dimensions, local.x(), local.y());
  AnalyticTruth truth;
  if (!point.valid) return truth;
  truth.valid = true;
  truth.z_mm = static_cast<float>(point.z_mm);
  truth.normal = (turn * point.normal).cast<float>();
  truth.kappa1 = static_cast<float>(point.kappa1);
  truth.kappa2 = static_cast<float>(point.kappa2);
  truth.shape_index = static_cast<float>(shape_index_of(point.kappa1, point.kappa2));
  truth.region = point.region;
  return truth;
}

AnalyticSurface make_analytic_surface(const AnalyticSurfaceSpec& spec) {
  AnalyticSurface surface;
  surface.spec = spec;
  surface.dimensions = resolve_dimensions(spec);

  // Half-extents of the turned silhouette along the scanner axes: the support function in the
  // shape's frame, evaluated at the scanner axes turned back.
  const Eigen::Matrix3d turn = turn_about_z(spec.rotate_deg);
  const Eigen::Vector2d x_axis_in_shape = turn.transpose().block<2, 1>(0, 0);
  const Eigen::Vector2d y_axis_in_shape = turn.transpose().block<2, 1>(0, 1);
  const double dx = spec.pixel_size_mm;
  const double half_columns =
      std::ceil(analytic_silhouette_extent_mm(spec.shape, surface.dimensions, x_axis_in_shape) /
                dx) +
      spec.margin_px;
  const double half_rows =
      std::ceil(analytic_silhouette_extent_mm(spec.shape, surface.dimensions, y_axis_in_shape) /
                dx) +
      spec.margin_px;
  const double pixels = (2.0 * half_columns + 1.0) * (2.0 * half_rows + 1.0);
  if (!(pixels <= kMaxPixels)) {
    FieldCheck(spec.shape)
        .fail("pixel_size_mm", dx,
              "the grid would exceed " + number_text(kMaxPixels) +
                  " pixels; use a larger pixel size or a smaller radius");
  }
  const int width = 2 * static_cast<int>(half_columns) + 1;
  const int height = 2 * static_cast<int>(half_rows) + 1;

  surface.range = RangeImage(width, height, dx, dx);
  surface.range.origin_x_mm = -half_columns * dx;
  surface.range.origin_y_mm = -half_rows * dx;
  surface.truth = PixelGrid<AnalyticTruth>(width, height);
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const AnalyticTruth truth = analytic_truth_at(
          spec, surface.dimensions, surface.range.x_mm(column), surface.range.y_mm(row));
      surface.truth(column, row) = truth;
      if (truth.valid) surface.range.z_mm(column, row) = truth.z_mm;
    }
  }

  if (spec.noise_mm > 0.0) {
    SeededNormal normal(spec.seed);
    for (std::size_t i = 0; i < surface.truth.size(); ++i) {
      if (!surface.truth[i].valid) continue;
      surface.range.z_mm[i] =
          static_cast<float>(surface.truth[i].z_mm + spec.noise_mm * normal.next());
    }
  }

  GroundTruthPose pose;
  pose.part = analytic_shape_name(spec.shape);
  pose.rotation = turn;
  surface.range.ground_truth = pose;
  return surface;
}

double analytic_region_area_mm2(const AnalyticSurface& surface, int region) {
  const double cell_area_mm2 = surface.range.pixel_size_x_mm * surface.range.pixel_size_y_mm;
  double area_mm2 = 0.0;
  for (const AnalyticTruth& truth : surface.truth.values()) {
    if (truth.valid && truth.region == region) area_mm2 += cell_area_mm2 / truth.normal.z();
  }
  return area_mm2;
}

std::array<Eigen::Vector3f, 3> box_corner_face_normals(const AnalyticSurfaceSpec& spec) {
  const Eigen::Matrix3d turn = turn_about_z(spec.rotate_deg);
  std::array<Eigen::Vector3f, 3> normals;
  const auto shape_normals = box_corner_shape_normals();
  for (std::size_t k = 0; k < 3; ++k) normals[k] = (turn * shape_normals[k]).cast<float>();
  return normals;
}

}  // namespace cosmos
