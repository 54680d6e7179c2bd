#pragma once
// The parts on the conveyor: meshes placed on the belt at known poses, and the belt motion.
//
// Parts are placed in the belt frame: the frame that rides with the belt and coincides with
// the scanner frame at encoder tick 0. At tick e the belt has moved by
// s = e · encoder_mm_per_tick along +y, so a point p_belt is at p_scanner = p_belt + (0, s, 0):
// T_scanner_belt(s) is a pure translation. A part's T_belt_part is therefore T_scanner_part
// at tick 0, exactly: the ground truth of a simulated scan.
//
// The scanner traces its rays in the belt frame (the laser sheet y_scanner = 0 is the plane
// y_belt = −s), so the ray-tracing structure is built once and never moves.
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "scanner/scanner_model.hpp"
#include "sim/belt_interval_index.hpp"
#include "sim/height_bound_grid.hpp"
#include "sim/mesh.hpp"

namespace cosmos {

class EmbreeScene;

struct PlacedPart {
  std::string name;
  int mesh = 0;
  Eigen::Isometry3d T_belt_part = Eigen::Isometry3d::Identity();
  Eigen::AlignedBox3d bounds_mm;  // tight box of the placed vertices, belt frame
  HeightBoundGrid height_bounds;  // coarse height bounds, to skip rays that cannot hit it
};

class ConveyorScene {
 public:
  // Each mesh is stored once, however many parts use it; parts are placements of it
  // (embree_scene.hpp), so moving one is cheap.
  ConveyorScene();
  ~ConveyorScene();
  ConveyorScene(const ConveyorScene&) = delete;
  ConveyorScene& operator=(const ConveyorScene&) = delete;

  // Uploads a part mesh (its own frame, mm) once; several parts may share it.
  int add_mesh(const TriangleMesh& mesh);
  // Places a part. Parts must not touch: std::invalid_argument when its bounding box overlaps
  // another part's in x and y (a conservative test: boxes, not surfaces).
  int add_part(std::string name, int mesh, const Eigen::Isometry3d& T_belt_part);
  // Moves a placed part (model views turn one part through many poses). No touching check.
  void move_part(int part, const Eigen::Isometry3d& T_belt_part);
  // Makes added or moved parts visible to the rays; required before scanning.
  void commit();

  const std::vector<PlacedPart>& parts() const { return parts_; }
  // Mesh `index` of add_mesh, in its own frame (std::out_of_range when there is none).
  const TriangleMesh& mesh(int index) const { return meshes_.at(static_cast<std::size_t>(index)); }
  // Calls visit(part) for each part whose y extent (belt frame) meets [y_low_mm, y_high_mm],
  // in a fixed order; as of the last commit(). Allocation-free.
  template <class Visit>
  void for_each_part_meeting_y(double y_low_mm, double y_high_mm, Visit&& visit) const {
    parts_along_belt_.for_each_meeting(
        y_low_mm, y_high_mm, [&](int part) { visit(parts_[static_cast<std::size_t>(part)]); });
  }
  Eigen::AlignedBox3d bounds_mm() const;  // all parts; empty box without parts
  // The top of the tallest part (belt frame), as of the last commit(); 0 without parts.
  double highest_z_mm() const { return highest_z_mm_; }
  const EmbreeScene& embree() const { return *embree_; }

 private:
  std::unique_ptr<EmbreeScene> embree_;
  std::vector<TriangleMesh> meshes_;  // for the parts' height bounds
  std::vector<PlacedPart> parts_;
  BeltIntervalIndex parts_along_belt_;
  double highest_z_mm_ = 0.0;
};

// The belt's displacement at a tick count, as the transform from belt to scanner frame.
Eigen::Isometry3d T_scanner_belt(const ScannerParameters& parameters, std::int64_t encoder_ticks);

// The profiles (indices k; encoder tick k · ticks_per_profile) whose laser sheet sweeps the
// parts' y extent extended by margin_mm on both sides, in exposure order (first < last).
struct ProfileRange {
  std::int64_t first = 0;
  std::int64_t last = -1;
  std::int64_t count() const { return last - first + 1; }
};
ProfileRange profiles_covering(const ConveyorScene& scene, const ScannerParameters& parameters,
                               double margin_mm);

// y of the laser sheet in the belt frame when profile k is exposed.
double laser_y_belt_mm(const ScannerParameters& parameters, std::int64_t profile_index);

}  // namespace cosmos
