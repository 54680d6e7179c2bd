#pragma once
// The COSMOS of one view (§3.2.2): per CSMP its area, orientation G0 (Eq. 3.7), shape index,
// mean curvedness R_m (Eq. 3.16) and connectivity list V (Eq. 3.10); support functions
// G1/G2 (Eqs. 3.14-3.15) aggregated per Gauss-map point by shape index.
#include <Eigen/Core>
#include <vector>

#include "core/segmentation/csmp_segmentation.hpp"
#include "core/surface/darboux_frame_field.hpp"
#include "core/surface/shape_index.hpp"

namespace cosmos {

struct PatchNeighbor {
  int patch = 0;
  int shared_boundary_pixels = 0;  // strength of the adjacency (§5.4.3)
};

struct Csmp {
  int id = 0;
  double area_mm2 = 0;
  Eigen::Vector3d mean_normal = Eigen::Vector3d::UnitZ();  // G0, Eq. 3.7 (unit)
  double shape_index = 0;  // area-weighted mean; 2.0 for planar patches
  double shape_index_min = 0;
  double shape_index_max = 0;
  double mean_curvedness_per_mm = 0;  // R_m, Eq. 3.16
  Eigen::Vector3d centroid_mm = Eigen::Vector3d::Zero();
  int pixels = 0;
  bool planar = false;
  std::vector<PatchNeighbor> neighbors;  // V(P), Eq. 3.10, ascending id
};

// One term of G1/G2 at a Gauss-map point: all patches mapped there with this shape index.
struct SupportTerm {
  double shape_index = 0;
  double area_mm2 = 0;         // G1 coefficient of e^{j t S_I}
  double curvedness_area = 0;  // G2 coefficient: sum of R_m * area
  std::vector<int> patches;
};

struct GaussMapPoint {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  std::vector<SupportTerm> terms;
};

struct CosmosView {
  std::vector<Csmp> patches;
  std::vector<GaussMapPoint> gauss_map;  // support functions G1, G2
  double visible_area_mm2 = 0;
};

// Patches whose G0 lie within this angle share a Gauss-map point (a discrete dS).
inline constexpr double kGaussMapMergeDeg = 2.0;
// Patches whose mean S_I differ by less than this aggregate into one support term.
inline constexpr double kSupportShapeIndexTolerance = 0.005;

CosmosView build_cosmos_view(const DarbouxFrameField& frames, const ShapeIndexField& field,
                             const CsmpSegmentation& segmentation);

}  // namespace cosmos
