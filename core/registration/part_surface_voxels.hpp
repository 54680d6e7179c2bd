#pragma once
// Which voxels of a regular grid over a part's frame hold a control point of any of the part's
// views: what the pose search's distance field (part_distance_field.hpp) is the distance
// transform of. The model base keeps it per part, the occupied voxels as run lengths
// (occupied_cell_runs.hpp), so that a recognizer builds every part's field without unpacking
// the part's views: unpacking every view of every part to find its voxels made a catalog of
// hundreds of parts take many times longer to become ready than to read.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/parameter_visitor.hpp"

namespace cosmos {

struct PartDistanceFieldParameters {
  double voxel_mm = 2.0;
  double margin_mm = 12.0;  // the grid extends this far beyond the points

  template <class Visitor>
  void visit(Visitor& v) {
    v("voxel_mm", voxel_mm, "distance field voxel, mm", Range::above(0, 100));
    v("margin_mm", margin_mm, "the field extends this far beyond the part, mm", Range{0, 1e3});
  }
};

// A grid never holds more voxels (16 Mi; a 500 mm part at the default 2 mm voxel fits):
// points spread wider get a coarser voxel than asked for.
inline constexpr std::size_t kMaxSurfaceVoxels = std::size_t{1} << 24;

struct PartSurfaceVoxels {
  Eigen::Vector3d origin_mm = Eigen::Vector3d::Zero();  // centre of voxel (0, 0, 0)
  double voxel_mm = 0.0;
  std::array<int, 3> size{0, 0, 0};  // voxels per axis, x fastest in the runs
  std::size_t occupied_voxels = 0;
  std::vector<std::uint8_t> occupied_runs;  // empty, occupied, empty, ... voxels

  bool empty() const { return occupied_voxels == 0; }
  // In double: a crafted size cannot overflow it.
  double voxel_count() const {
    return static_cast<double>(size[0]) * static_cast<double>(size[1]) *
           static_cast<double>(size[2]);
  }
};

// The voxels of `points_part_mm` (the part's surface points in its frame; non-finite ones are
// left out), each in the voxel its point rounds to. Empty without a finite point or with
// parameters out of range.
PartSurfaceVoxels part_surface_voxels(const std::vector<Eigen::Vector3d>& points_part_mm,
                                      const PartDistanceFieldParameters& parameters);

// Is the grid one part_surface_voxels can make: at least 2 voxels per axis, at most
// kMaxSurfaceVoxels, a finite origin and a positive voxel? (The runs are not read.)
bool part_surface_voxel_grid_bounded(const PartSurfaceVoxels& voxels);

// Is the grid bounded and do the runs cover it exactly with occupied_voxels occupied? An
// empty set is consistent.
bool part_surface_voxels_consistent(const PartSurfaceVoxels& voxels);

}  // namespace cosmos
