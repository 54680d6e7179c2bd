#pragma once
// The closed-form geometry of each analytic shape in its own frame (before the rotate_deg
// turn about z): the top surface over a point (x, y), and the extent of the silhouette.
// analytic_surface.cpp rotates, samples and adds noise; this file only knows the formulas.
#include <Eigen/Core>
#include <array>

#include "sim/analytic_surface.hpp"

namespace cosmos {

// The surface point seen from +z above (x, y), in the shape's frame, in double precision.
struct ShapePoint {
  bool valid = false;
  double z_mm = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, n_z > 0
  double kappa1 = 0.0;  // 1/mm, convex towards +z positive, kappa1 >= kappa2
  double kappa2 = 0.0;
  int region = 0;
};

ShapePoint analytic_shape_point(AnalyticShape shape, const AnalyticDimensions& dimensions,
                                double x_mm, double y_mm);

// Support function of the silhouette: max over the silhouette's points p of p . direction
// (direction a unit xy vector). Every silhouette is centrally symmetric about the origin.
double analytic_silhouette_extent_mm(AnalyticShape shape, const AnalyticDimensions& dimensions,
                                     const Eigen::Vector2d& direction);

// The box corner's visible face normals in the shape's frame (regions 0, 1, 2).
std::array<Eigen::Vector3d, 3> box_corner_shape_normals();

}  // namespace cosmos
