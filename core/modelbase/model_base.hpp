#pragma once
// The in-memory model base (thesis ch. 4, Fig. 5.3): every catalog part seen from the
// view-sphere directions, each view with its COSMOS, shape-spectrum moments and what
// registration needs; views grouped per part into clusters whose centroids form the first
// tier of spectral model-view selection (§5.2), the views the second.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/modelbase/view_extent.hpp"
#include "core/modelbase/view_signature.hpp"
#include "core/registration/packed_registration_points.hpp"
#include "core/registration/part_surface_voxels.hpp"
#include "core/registration/registration_points.hpp"
#include "core/representation/cosmos_view.hpp"
#include "core/representation/shape_spectrum.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

// A stable pose of the part lying on the belt (z up, the belt the plane z = 0): the rotation
// with its resting face down and no turn about the vertical, the height of the part's origin
// above the belt, and the chance a dropped part settles so. Any turn about the vertical and
// any place on the belt rest as well.
struct RestingPose {
  Eigen::Matrix3d R_belt_part = Eigen::Matrix3d::Identity();
  double height_mm = 0;
  double probability = 0;
};

struct ModelPart {
  std::string name;
  std::string mesh;        // as written in the catalog
  double size_mm = 0;      // largest extent after scaling
  double diameter_mm = 0;  // largest distance between two mesh vertices (for ADD-S)
  bool symmetric = false;
  std::vector<RestingPose> resting_poses;  // most likely first
  // The corners of the part's convex hull: its lowest point in any pose.
  std::vector<Eigen::Vector3d> hull_vertices_mm;
  // Of its views' control points, all in the part frame: the voxels they occupy (what the
  // pose search's distance field is built from) and an even sample of them (what a pose must
  // not place over measured belt). part_surface_summary.hpp computes both.
  PartSurfaceVoxels surface_voxels;
  std::vector<Eigen::Vector3d> surface_sample_mm;
  // The parts of one of whose views this part's quick field fit is as close as a scan's to its
  // own part (core/recognition/confusable_parts.hpp): indices into ModelBase::parts, ascending.
  std::vector<int> confusable_parts;

  // The chance the kept resting poses cover: below 1 when unlikely ones were left out.
  double resting_coverage() const {
    double coverage = 0;
    for (const RestingPose& pose : resting_poses) coverage += pose.probability;
    return coverage;
  }
};

struct ModelBaseView {
  int part_index = 0;
  int view_index = 0;  // index into view_directions()
  Eigen::Vector3d direction_part = Eigen::Vector3d::UnitZ();
  RigidTransform T_scanner_part;    // pose the view was scanned in
  CosmosView cosmos;                // patches and connectivity
  MomentVector moments{};           // Eqs. 4.1-4.2 + planar fraction
  RegistrationPoints registration;  // model surface for ch. 6
  // The compact form the base keeps for every view (about 3 bytes per point, not 104): what
  // the builder produces and read_model_base fills, zero-copy from the file; `registration` is
  // then empty, and the recognizer unpacks (unpack_registration_points) only the candidate
  // views of §5.2. write_model_base packs `registration` when this one is empty.
  PackedRegistrationPoints registration_packed;
  // The mean of its control points, in the view's frame (zero without any): where the pose
  // search puts a scene's centroid (part_surface_summary.hpp computes it).
  Eigen::Vector3d control_point_centroid_mm = Eigen::Vector3d::Zero();
  // How tall and wide the part is seen from near this view, for the views the pose search
  // starts from (view_extent.hpp); unbounded for the others.
  ViewExtent extent;
  // Its control points' metric signature (view_signature.hpp), by which a search over many
  // parts ranks them before fitting any.
  ViewSignature signature;

  int control_point_count() const {
    return registration.size() > 0 ? registration.size() : registration_packed.size();
  }
};

// View indices follow the view sphere's fixed order (sim/view_sphere.hpp, two subdivisions:
// face by face, child by child, the middle child last). The indices that are 3 mod 4 are the
// middle children of the once-subdivided faces: the 80-view sphere, evenly spread, within
// 0.04 degrees of its face centres (sim/model_base_build/view_direction_subset.hpp). Bases of 20 or
// 80 views hold only such views.
inline bool is_once_subdivided_view(int view_index) { return view_index % 4 == 3; }

struct ViewCluster {
  int part_index = 0;
  std::vector<int> views;   // indices into ModelBase::views
  MomentVector centroid{};  // mean moment vector of its views (§4.4.2)
};

struct ModelBase {
  // Raised whenever what a build writes changes (layout or content), so that caches and
  // readers refuse or rebuild what an older build wrote. 2: registration streams
  // (docs/architecture.md), and no patch without pixels. 3: the parts' resting poses and hulls.
  // 4: the parts' surface voxels and samples, the views' control-point centroids. 5: the parts'
  // confusable parts. 6: those listed by quick fits scored on farthest-point subsets. 7: the
  // start views' extents, and the confusable parts listed by quick fits that start from the
  // views the probe's extent allows. 8: every view's metric signature.
  static constexpr std::uint32_t kFormatVersion = 8;
  std::string catalog_hash;     // content hash of the catalog and its meshes
  std::string parameters_text;  // every COSMOS/scanner/grouping parameter, canonical text
  std::vector<ModelPart> parts;
  std::vector<ModelBaseView> views;
  std::vector<ViewCluster> clusters;
};

}  // namespace cosmos
