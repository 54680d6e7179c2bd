#include "core/indexing/patch_pair_key.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosmos {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// A curved patch's bin coordinate in [0, shape_index_bins).
double shape_coordinate(const Csmp& patch, const PatchPairKeyParameters& parameters) {
  if (patch.planar) return parameters.shape_index_bins;
  const double bins = parameters.shape_index_bins;
  return std::clamp((patch.shape_index + 1.0) / 2.0 * bins, 0.0, std::nextafter(bins, 0.0));
}

// The bin a coordinate falls in, and the nearer neighbouring one (-1: none) among `count`
// bins; `categorical`: no neighbour.
struct BinChoice {
  int bins[2] = {0, -1};
  int size() const { return bins[1] < 0 ? 1 : 2; }
};

BinChoice bin_and_nearer_neighbour(double coordinate, int count, bool categorical) {
  BinChoice choice;
  const int bin = std::clamp(static_cast<int>(std::floor(coordinate)), 0, count - 1);
  choice.bins[0] = bin;
  if (categorical) return choice;
  const int neighbour = coordinate - bin < 0.5 ? bin - 1 : bin + 1;
  if (neighbour >= 0 && neighbour < count) choice.bins[1] = neighbour;
  return choice;
}

int key_of_bins(int shape_a, int shape_b, int angle, int distance,
                const PatchPairKeyParameters& parameters) {
  return ((shape_a * parameters.shape_bins() + shape_b) * parameters.angle_bins() + angle) *
             parameters.centroid_distance_bins +
         distance;
}

}  // namespace

int PatchPairKeyParameters::angle_bins() const {
  return std::max(1, static_cast<int>(std::ceil(180.0 / normal_angle_bin_deg - 1e-9)));
}

int PatchPairKeyParameters::key_count() const {
  return shape_bins() * shape_bins() * angle_bins() * centroid_distance_bins;
}

std::optional<PatchPairFeature> patch_pair_feature(const Csmp& a, const Csmp& b,
                                                   const PatchPairKeyParameters& parameters) {
  if (a.area_mm2 < parameters.min_patch_area_mm2 || b.area_mm2 < parameters.min_patch_area_mm2)
    return std::nullopt;
  const Eigen::Vector3d offset = b.centroid_mm - a.centroid_mm;
  PatchPairFeature feature;
  feature.distance = offset.norm() / parameters.centroid_distance_bin_mm;
  if (!(feature.distance < parameters.centroid_distance_bins)) return std::nullopt;
  const Eigen::Vector3d& normal = a.mean_normal;
  const Eigen::Vector3d lateral = offset - offset.dot(normal) * normal;
  if (!(lateral.norm() >= parameters.min_lateral_offset_mm)) return std::nullopt;
  const double cosine = std::clamp(a.mean_normal.dot(b.mean_normal), -1.0, 1.0);
  feature.angle = std::acos(cosine) * kDegPerRad / parameters.normal_angle_bin_deg;
  feature.shape_a = shape_coordinate(a, parameters);
  feature.shape_b = shape_coordinate(b, parameters);
  const Eigen::Vector3d y = lateral.normalized();
  feature.T_view_pair.rotation.col(0) = normal;
  feature.T_view_pair.rotation.col(1) = y;
  feature.T_view_pair.rotation.col(2) = normal.cross(y);
  feature.T_view_pair.translation_mm = 0.5 * (a.centroid_mm + b.centroid_mm);
  return feature;
}

int patch_pair_key(const PatchPairFeature& feature, const PatchPairKeyParameters& parameters) {
  const auto bin = [](double coordinate, int count) {
    return std::clamp(static_cast<int>(std::floor(coordinate)), 0, count - 1);
  };
  return key_of_bins(bin(feature.shape_a, parameters.shape_bins()),
                     bin(feature.shape_b, parameters.shape_bins()),
                     bin(feature.angle, parameters.angle_bins()),
                     bin(feature.distance, parameters.centroid_distance_bins), parameters);
}

int nearby_patch_pair_keys(const PatchPairFeature& feature,
                           const PatchPairKeyParameters& parameters,
                           std::array<int, kMaxNearbyPatchPairKeys>& keys) {
  const int curved_bins = parameters.shape_index_bins;
  const auto shape_choice = [&](double coordinate) {
    return coordinate >= curved_bins
               ? bin_and_nearer_neighbour(coordinate, parameters.shape_bins(), true)
               : bin_and_nearer_neighbour(coordinate, curved_bins, false);
  };
  const BinChoice shape_a = shape_choice(feature.shape_a);
  const BinChoice shape_b = shape_choice(feature.shape_b);
  const BinChoice angle = bin_and_nearer_neighbour(feature.angle, parameters.angle_bins(), false);
  const BinChoice distance =
      bin_and_nearer_neighbour(feature.distance, parameters.centroid_distance_bins, false);
  int count = 0;
  for (int i = 0; i < shape_a.size(); ++i)
    for (int j = 0; j < shape_b.size(); ++j)
      for (int k = 0; k < angle.size(); ++k)
        for (int l = 0; l < distance.size(); ++l)
          keys[static_cast<std::size_t>(count++)] = key_of_bins(
              shape_a.bins[i], shape_b.bins[j], angle.bins[k], distance.bins[l], parameters);
  return count;
}

}  // namespace cosmos
