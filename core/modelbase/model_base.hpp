#pragma once
// The in-memory model base (thesis ch. 4, Fig. 5.3): every catalog part seen from the
// view-sphere directions, each view with its COSMOS, shape-spectrum moments and what
// registration needs; views grouped per part into clusters whose centroids form the first
// tier of spectral model-view selection (§5.2), the views the second.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/registration/packed_registration_points.hpp"
#include "core/registration/registration_points.hpp"
#include "core/representation/cosmos_view.hpp"
#include "core/representation/shape_spectrum.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

struct ModelPart {
  std::string name;
  std::string mesh;        // as written in the catalog
  double size_mm = 0;      // largest extent after scaling
  double diameter_mm = 0;  // largest distance between two mesh vertices (for ADD-S)
  bool symmetric = false;
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
  // (docs/architecture.md), and no patch without pixels.
  static constexpr std::uint32_t kFormatVersion = 2;
  std::string catalog_hash;     // content hash of the catalog and its meshes
  std::string parameters_text;  // every COSMOS/scanner/grouping parameter, canonical text
  std::vector<ModelPart> parts;
  std::vector<ModelBaseView> views;
  std::vector<ViewCluster> clusters;
};

}  // namespace cosmos
