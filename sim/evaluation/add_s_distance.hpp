#pragma once
// Pose error of a rigid part as an average distance over its model points (Hodan et al.,
// "On Evaluation of 6D Object Pose Estimation", ECCV workshops 2016):
//   ADD   = mean_p | (R_t p + t_t) - (R_e p + t_e) |
//   ADD-S = mean_p min_q | (R_t p + t_t) - (R_e q + t_e) |
// ADD-S is the symmetric-safe one: a pose that maps the part onto itself (a ring turned by
// its symmetry angle) has ADD-S 0 but a large ADD. Points are in the part frame, mm.
//
// With the part's mesh, q ranges over its surface rather than over the points: a coarse CAD
// mesh of a surface of revolution has a few rings of vertices, and a turn about its axis that
// maps the surface onto itself moves each vertex between two of a ring's, which the
// vertex-to-vertex form counts as error (up to half the ring's spacing).
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "sim/mesh.hpp"
#include "sim/mesh_surface_distance.hpp"

namespace cosmos {

struct RigidPose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // T_scanner_part rotation
  Eigen::Vector3d t_mm = Eigen::Vector3d::Zero();
};

// ADD-S against one part's model points. The nearest-neighbour structure (an implicit k-d
// tree: the points reordered so that each range's middle point splits it) is built once and
// reused for every pose of that part; ~2,000 points take well under a millisecond per pose,
// where brute force is quadratic.
class AddSDistance {
 public:
  explicit AddSDistance(std::span<const Eigen::Vector3d> model_points_mm);
  // The mean over `model_points_mm` of the distance to the nearest point of `mesh`'s surface.
  AddSDistance(std::span<const Eigen::Vector3d> model_points_mm, const TriangleMesh& mesh);
  // ... to the nearest point of the surface `surface` measures (a hierarchy shared with the
  // simulated scanner's).
  AddSDistance(std::span<const Eigen::Vector3d> model_points_mm,
               std::unique_ptr<const MeshSurfaceDistance> surface);

  // mm; 0 when there are no model points.
  double add_s_mm(const RigidPose& truth, const RigidPose& estimate) const;

  // Squared distance (mm^2) from `query_mm` (part frame) to the nearest model point, or to
  // the nearest surface point when built with the mesh; +infinity when there are none.
  double nearest_squared_mm2(const Eigen::Vector3d& query_mm) const;

 private:
  void build(int begin, int end);
  void search(int begin, int end, const Eigen::Vector3d& query_mm, double& best_mm2) const;

  std::vector<Eigen::Vector3d> points_mm_;  // in k-d tree order
  std::vector<std::uint8_t> split_axis_;    // per point: the axis it splits its range on
  std::unique_ptr<const MeshSurfaceDistance> surface_;
};

// Plain ADD (point p against its own image), mm; 0 when there are no model points.
double add_mm(std::span<const Eigen::Vector3d> model_points_mm, const RigidPose& truth,
              const RigidPose& estimate);

}  // namespace cosmos
