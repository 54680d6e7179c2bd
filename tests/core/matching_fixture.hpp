#pragma once
// Views with known structure for the COSMOS matching and pose tests (§5.3): the analytic
// capsule, and a synthetic free-form relief, each analyzed once per process and cached, with
// the ground-truth region that holds most of each patch's pixels.
//
// The relief is a roof (two flanks tilted 20 degrees about y, joined by a cylindrical fillet
// of radius 20 mm along y) carrying a spherical bump on the left flank, a smaller bump and a
// spherical dent on the right flank, over a round footprint of radius 48 mm, so that turning
// it about z keeps the same surface in view. Its patch normals are far from parallel (the
// flanks and the features on them tilt), so they fix a rotation about z, and its patch graph
// is asymmetric (the left flank carries one feature, the right one two).
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "core/representation/cosmos_pipeline.hpp"
#include "sim/analytic_surface.hpp"

namespace cosmos::testing {

enum ReliefRegion { kLeftFlank = 0, kRightFlank, kRidge, kLeftBump, kRightBump, kRightDent };

inline constexpr double kReliefTiltRad = 20.0 * std::numbers::pi / 180.0;
inline constexpr double kReliefFilletMm = 20.0;
inline constexpr double kReliefFootprintMm = 48.0;
inline constexpr double kReliefPixelMm = 0.5;
inline constexpr double kReliefBaseHeightMm = 50.0;

struct ReliefFeature {
  double x_mm, y_mm, radius_mm, height_mm;  // height > 0: bump, < 0: dent
  ReliefRegion region;
};
inline constexpr ReliefFeature kReliefFeatures[] = {
    {-27, 6, 15, 5.5, kLeftBump}, {27, 20, 13, 5, kRightBump}, {25, -19, 14, -5, kRightDent}};

inline double relief_roof_mm(double x_mm) {
  const double fillet_half_width_mm = kReliefFilletMm * std::sin(kReliefTiltRad);
  const double ax = std::abs(x_mm);
  if (ax <= fillet_half_width_mm)
    return std::sqrt(kReliefFilletMm * kReliefFilletMm - x_mm * x_mm) - kReliefFilletMm;
  return kReliefFilletMm * (std::cos(kReliefTiltRad) - 1.0) -
         (ax - fillet_half_width_mm) * std::tan(kReliefTiltRad);
}

// The sphere of a feature: centred on the flank normal through the foot point, so the bump
// or dent stands `height` proud of (or sunk into) the flank.
inline Eigen::Vector3d relief_feature_centre(const ReliefFeature& f) {
  const double side = f.x_mm < 0 ? -1.0 : 1.0;
  const Eigen::Vector3d flank_normal(side * std::sin(kReliefTiltRad), 0, std::cos(kReliefTiltRad));
  const double depth_mm = f.radius_mm - std::abs(f.height_mm);
  return Eigen::Vector3d(f.x_mm, f.y_mm, relief_roof_mm(f.x_mm)) +
         (f.height_mm > 0 ? -depth_mm : depth_mm) * flank_normal;
}

// Part frame, before the turn about z.
inline double relief_height_mm(double x_mm, double y_mm) {
  double z = relief_roof_mm(x_mm);
  for (const ReliefFeature& f : kReliefFeatures) {
    const Eigen::Vector3d c = relief_feature_centre(f);
    const double r2 = (x_mm - c.x()) * (x_mm - c.x()) + (y_mm - c.y()) * (y_mm - c.y());
    if (r2 >= f.radius_mm * f.radius_mm) continue;
    const double h = std::sqrt(f.radius_mm * f.radius_mm - r2);
    z = f.height_mm > 0 ? std::max(z, c.z() + h) : std::min(z, c.z() - h);
  }
  return z;
}

inline ReliefRegion relief_region(double x_mm, double y_mm) {
  if (std::abs(relief_height_mm(x_mm, y_mm) - relief_roof_mm(x_mm)) > 1e-9) {
    // On a bump or in a dent: the feature with the nearest foot point (they are far apart).
    double nearest_mm = std::numeric_limits<double>::infinity();
    ReliefRegion region = kRidge;
    for (const ReliefFeature& f : kReliefFeatures) {
      const double d = std::hypot(x_mm - f.x_mm, y_mm - f.y_mm);
      if (d < nearest_mm) {
        nearest_mm = d;
        region = f.region;
      }
    }
    return region;
  }
  if (std::abs(x_mm) <= kReliefFilletMm * std::sin(kReliefTiltRad)) return kRidge;
  return x_mm < 0 ? kLeftFlank : kRightFlank;
}

// Pixel (x, y) of the scanner sees the part point Rz(-turn) (x, y).
inline Eigen::Vector2d relief_part_point(double x_mm, double y_mm, double turn_deg) {
  const double a = turn_deg * std::numbers::pi / 180.0;
  return {std::cos(a) * x_mm + std::sin(a) * y_mm, -std::sin(a) * x_mm + std::cos(a) * y_mm};
}

inline RangeImage make_relief_range_image(double turn_deg, double noise_mm, std::uint64_t seed) {
  const int half = static_cast<int>(kReliefFootprintMm / kReliefPixelMm) + 4;
  const int n = 2 * half + 1;
  RangeImage image(n, n, kReliefPixelMm, kReliefPixelMm);
  image.origin_x_mm = image.origin_y_mm = -half * kReliefPixelMm;
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> noise(0.0, noise_mm);
  for (int row = 0; row < n; ++row) {
    for (int column = 0; column < n; ++column) {
      const double x = image.x_mm(column);
      const double y = image.y_mm(row);
      if (std::hypot(x, y) > kReliefFootprintMm) {
        image.z_mm(column, row) = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      const Eigen::Vector2d p = relief_part_point(x, y, turn_deg);
      image.z_mm(column, row) = static_cast<float>(
          kReliefBaseHeightMm + relief_height_mm(p.x(), p.y()) + noise(generator));
    }
  }
  return image;
}

// A view and, per patch id, the truth region holding most of its pixels.
struct LabelledView {
  CosmosView view;
  std::map<int, int> region_of_patch;
  Eigen::Matrix3d R_scanner_part = Eigen::Matrix3d::Identity();
};

template <class RegionAt>
std::map<int, int> majority_regions(const ViewAnalysis& analysis, RegionAt&& region_at) {
  std::map<int, std::map<int, int>> votes;
  const auto& labels = analysis.segmentation.patch_of_pixel;
  for (int row = 0; row < labels.height(); ++row) {
    for (int column = 0; column < labels.width(); ++column) {
      const int patch = labels(column, row);
      if (patch >= 0) ++votes[patch][region_at(column, row)];
    }
  }
  std::map<int, int> majority;
  for (const auto& [patch, counts] : votes) {
    int best = -1;
    int best_count = -1;
    for (const auto& [region, count] : counts) {
      if (count > best_count) {
        best = region;
        best_count = count;
      }
    }
    majority[patch] = best;
  }
  return majority;
}

inline Eigen::Matrix3d rotation_about_z_deg(double angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  Eigen::Matrix3d r;
  r << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return r;
}

// Turns 0 and 40 degrees, noise 0.01 mm.
inline const LabelledView& relief_view(int turn_deg) {
  static std::map<int, LabelledView> cache;
  auto found = cache.find(turn_deg);
  if (found != cache.end()) return found->second;
  const RangeImage image = make_relief_range_image(turn_deg, 0.01, 7 + turn_deg);
  const ViewAnalysis analysis = analyze_view(image, CosmosParameters{});
  LabelledView labelled;
  labelled.view = analysis.view;
  labelled.region_of_patch = majority_regions(analysis, [&](int column, int row) {
    const Eigen::Vector2d p = relief_part_point(image.x_mm(column), image.y_mm(row), turn_deg);
    return static_cast<int>(relief_region(p.x(), p.y()));
  });
  labelled.R_scanner_part = rotation_about_z_deg(turn_deg);
  return cache.emplace(turn_deg, std::move(labelled)).first->second;
}

// Analytic shapes at noise 0.01 mm; regions as AnalyticTruth::region (capsule: 0 and 2 the
// caps, 1 the ridge).
inline const LabelledView& analytic_view(AnalyticShape shape, int rotate_deg) {
  static std::map<std::pair<int, int>, LabelledView> cache;
  const std::pair<int, int> key{static_cast<int>(shape), rotate_deg};
  auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  AnalyticSurfaceSpec spec;
  spec.shape = shape;
  spec.rotate_deg = rotate_deg;
  spec.noise_mm = 0.01;
  spec.seed = 11;
  const AnalyticSurface surface = make_analytic_surface(spec);
  const ViewAnalysis analysis = analyze_view(surface.range, CosmosParameters{});
  LabelledView labelled;
  labelled.view = analysis.view;
  labelled.region_of_patch = majority_regions(
      analysis, [&](int column, int row) { return surface.truth(column, row).region; });
  labelled.R_scanner_part = rotation_about_z_deg(rotate_deg);
  return cache.emplace(key, std::move(labelled)).first->second;
}

}  // namespace cosmos::testing
