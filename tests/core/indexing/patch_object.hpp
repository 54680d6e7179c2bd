#pragma once
// Two made-up parts as CSMPs in their own frame (shape index, mean normal, centroid, area,
// adjacency), and their COSMOS seen in any pose, for the vote index's tests: a block with flat
// faces and two curved blends, and a rounder part with caps and a saddle.
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/representation/cosmos_view.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos::testing {

struct ObjectPatch {
  double shape_index;
  bool planar;
  Eigen::Vector3d normal_part;
  Eigen::Vector3d centroid_part_mm;
  double area_mm2;
  std::vector<int> neighbors;
};

inline std::vector<ObjectPatch> block_patches() {
  return {{2.0, true, {0, 0, 1}, {0, 0, 20}, 900, {1, 2, 3, 4}},
          {2.0, true, {1, 0, 0}, {25, 0, 5}, 400, {0, 2, 4}},
          {0.5, false, {0, 1, 1}, {0, 20, 10}, 300, {0, 1, 3}},
          {-0.5, false, {-1, 0, 0.3}, {-22, 3, 6}, 250, {0, 2, 4}},
          {2.0, true, {0, -1, 0}, {0, -18, 5}, 350, {0, 1, 3}}};
}

inline std::vector<ObjectPatch> round_patches() {
  return {{0.9, false, {0, 0, 1}, {0, 0, 30}, 600, {1, 2, 3}},
          {0.3, false, {1, 1, 0.5}, {14, 14, 15}, 300, {0, 2}},
          {-0.2, false, {-1, 0.2, 0.4}, {-18, 2, 12}, 280, {0, 1, 3}},
          {0.9, false, {0.2, -1, 0.6}, {3, -17, 14}, 320, {0, 2}}};
}

// The object's patches seen in the frame `T_frame_part` puts it in.
inline CosmosView object_view(const std::vector<ObjectPatch>& object,
                              const RigidTransform& T_frame_part) {
  CosmosView view;
  for (std::size_t i = 0; i < object.size(); ++i) {
    Csmp patch;
    patch.id = static_cast<int>(i);
    patch.shape_index = object[i].shape_index;
    patch.planar = object[i].planar;
    patch.mean_normal = T_frame_part.rotate(object[i].normal_part.normalized());
    patch.centroid_mm = T_frame_part.apply(object[i].centroid_part_mm);
    patch.area_mm2 = object[i].area_mm2;
    for (int neighbor : object[i].neighbors) patch.neighbors.push_back({neighbor, 10});
    view.patches.push_back(patch);
  }
  return view;
}

inline ModelBaseView object_model_view(const std::vector<ObjectPatch>& object, int part,
                                       const RigidTransform& T_scanner_part) {
  ModelBaseView view;
  view.part_index = part;
  view.T_scanner_part = T_scanner_part;
  view.cosmos = object_view(object, T_scanner_part);
  return view;
}

}  // namespace cosmos::testing
