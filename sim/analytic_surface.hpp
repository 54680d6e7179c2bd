#pragma once
// Analytic test surfaces rendered as range images with exact per-pixel ground truth (height,
// normal, principal curvatures, shape index, region), so that every COSMOS stage can be
// tested against numbers known in closed form.
//
// Frame: the sensor looks down -z from +z; z is the height towards the sensor. Pixel
// (column i, row j) is sampled exactly at x = x0 + i*dx, y = y0 + j*dy. Every shape is built
// in its own frame centred on the z axis, then rotated by rotate_deg about z; the grid is
// centred on the origin (the middle pixel sits at x = y = 0) and covers the rotated
// silhouette plus a margin of NaN pixels. Where a ray meets the part twice the top (largest
// z) surface is the one seen.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/pixel_grid.hpp"
#include "core/range_image.hpp"

namespace cosmos {

enum class AnalyticShape {
  kSphere,
  kCup,
  kCylinder,
  kSaddle,
  kPlane,
  kTorus,
  kEllipsoid,
  kCapsule,
  kBoxCorner
};

// "sphere", "cup", ..., "box-corner" (the CLI spelling; "box_corner" is accepted too).
// Unknown names throw InputError listing the valid ones.
AnalyticShape parse_analytic_shape(std::string_view name);
std::string analytic_shape_name(AnalyticShape shape);
// "sphere, cup, cylinder, saddle, plane, torus, ellipsoid, capsule, box-corner"
std::string analytic_shape_names();

// Shape sizes left unset derive from radius_mm = R; the values in brackets are those at the
// default R = 25 mm, so one --radius-mm scales every shape.
struct AnalyticSurfaceSpec {
  AnalyticShape shape = AnalyticShape::kSphere;
  double radius_mm = 25.0;     // sphere, cup, cylinder radius; saddle z = (x^2 - y^2) / (2R)
  double pixel_size_mm = 0.5;  // dx = dy
  double noise_mm = 0.0;       // standard deviation of the Gaussian noise added to z
  std::uint64_t seed = 1;      // seed of the noise generator
  double rotate_deg = 0.0;     // rotation of the part about the viewing axis z
  int margin_px = 4;           // NaN pixels around the silhouette

  std::optional<double> cylinder_length_mm;     // 3.2 R [80]; the axis is y before rotation
  std::optional<double> saddle_half_width_mm;   // 0.8 R [20]; square window |x|, |y| <= w
  std::optional<double> plane_half_width_mm;    // R [25]; square window |x|, |y| <= w
  std::optional<double> plane_tilt_deg;         // 20; z = tan(tilt) x
  std::optional<double> torus_major_radius_mm;  // 1.2 R [30]; lying flat, axis z
  std::optional<double> torus_minor_radius_mm;  // 0.48 R [12]
  std::optional<Eigen::Vector3d> ellipsoid_semi_axes_mm;  // (1.2, 0.8, 0.6) R [30, 20, 15]
  std::optional<double> capsule_radius_mm;                // 0.6 R [15]; axis x before rotation
  std::optional<double> capsule_length_mm;  // 1.6 R [40]: the cylinder between the caps
  std::optional<double> box_edge_mm;        // 1.6 R [40]; cube corner seen along its diagonal
};

// Every size of a spec made concrete (defaults applied).
struct AnalyticDimensions {
  double radius_mm = 0.0;
  double cylinder_length_mm = 0.0;
  double saddle_half_width_mm = 0.0;
  double plane_half_width_mm = 0.0;
  double plane_tilt_deg = 0.0;
  double torus_major_radius_mm = 0.0;
  double torus_minor_radius_mm = 0.0;
  Eigen::Vector3d ellipsoid_semi_axes_mm = Eigen::Vector3d::Zero();
  double capsule_radius_mm = 0.0;
  double capsule_length_mm = 0.0;
  double box_edge_mm = 0.0;
};

// Applies the defaults; throws InputError naming the field when a value is not finite or out
// of range (non-positive size, negative noise, torus minor radius >= major radius, ...).
AnalyticDimensions resolve_dimensions(const AnalyticSurfaceSpec& spec);

// Exact, noise-free surface properties at one pixel centre.
struct AnalyticTruth {
  bool valid = false;
  float z_mm = 0.0f;
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();  // unit, n_z > 0 (towards the sensor)
  // Principal curvatures, 1/mm, kappa1 >= kappa2, positive where the surface is convex
  // towards the sensor (sphere +1/R, cup -1/R, cylinder ridge +1/R and 0).
  float kappa1 = 0.0f;
  float kappa2 = 0.0f;
  // Eq. 3.2 in the convex-positive convention: S_I = 1/2 + atan((k1 + k2) / (k1 - k2)) / pi,
  // sphere 1, cup 0, ridge 0.75, symmetric saddle 0.5; planar points get the symbolic 2.0.
  float shape_index = 2.0f;
  // capsule: 0 left cap (x < 0 before rotation), 1 cylindrical ridge, 2 right cap;
  // box_corner: the visible face 0..2 (see box_corner_face_normals); other shapes 0.
  int region = 0;
};

struct AnalyticSurface {
  AnalyticSurfaceSpec spec;
  AnalyticDimensions dimensions;
  // z with noise; origin, pixel size and ground truth (part = shape name, rotation = the
  // rotate_deg turn about z, translation 0) filled in.
  RangeImage range;
  PixelGrid<AnalyticTruth> truth;  // same grid as range, noise-free
};

// Throws InputError (naming the field) for invalid specs and for grids over 16M pixels.
AnalyticSurface make_analytic_surface(const AnalyticSurfaceSpec& spec);

// The surface properties at the scanner-frame point (x_mm, y_mm), rotation included; the
// same function make_analytic_surface samples at the pixel centres.
AnalyticTruth analytic_truth_at(const AnalyticSurfaceSpec& spec,
                                const AnalyticDimensions& dimensions, double x_mm, double y_mm);

// Surface area (mm^2) of one region over the valid pixel cells: the sum, over its valid
// pixels, of dx*dy / n_z at the pixel centre, i.e. the per-pixel area estimator the pipeline
// applies to estimated normals, fed with the exact ones. Exact for planar faces up to the
// cells cut by the face's border; it misses part of steep rims, where 1/n_z diverges (the
// capsule's half cylinder of radius 15 mm at 0.5 mm pixels: -11%, at 0.125 mm: -6%).
double analytic_region_area_mm2(const AnalyticSurface& surface, int region);

// The outward unit normals of the three visible faces of the box corner (regions 0, 1, 2) in
// the scanner frame, rotation included. Each has n_z = 1/sqrt(3); before rotation their xy
// directions point at 90, 210 and 330 degrees.
std::array<Eigen::Vector3f, 3> box_corner_face_normals(const AnalyticSurfaceSpec& spec);

}  // namespace cosmos
