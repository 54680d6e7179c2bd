#pragma once
// RAII over Embree 3 for the simulated scanner: one device, each mesh's bounding-volume
// hierarchy built once in the mesh's own frame, and the placements of those meshes in the
// world (T_world_mesh). A ray is traced in the frame of each placed mesh it may meet (the
// placements the ray packet's box meets along the belt, belt_interval_index.hpp), carried
// there in double precision.
//
// Why not one Embree scene over the whole belt: baking every placed part's triangles into it
// costs memory per part (a thousand-part run held gigabytes), and Embree's own instances carry
// rays into the mesh frame in float, whose rounding at a part metres down the belt (micrometres)
// exceeds the offset that keeps an occlusion ray off its own surface. Here a mesh is stored
// once however many parts use it, moving a part is a matrix, and the rays' coordinates are
// given relative to a frame near them (frame_y_mm), so their precision does not depend on how
// far the belt has run.
//
// Determinism: the device runs one thread, so the hierarchies are built the same way every
// run, and the placements are visited in a fixed order. Embree's own thread pool would also
// compete with the other work of a two-core cell computer.
//
// Only .cpp files include this header: it brings in Embree's C API.
#include <embree3/rtcore.h>

#include <Eigen/Geometry>
#include <vector>

#include "sim/belt_interval_index.hpp"
#include "sim/mesh.hpp"

namespace cosmos {

class EmbreeScene {
 public:
  EmbreeScene();
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Uploads a mesh (vertices in its own frame, mm), builds its hierarchy and returns its
  // index. The mesh must have at least one triangle with valid indices
  // (std::invalid_argument otherwise).
  int add_mesh(const TriangleMesh& mesh);
  // Places mesh `mesh_index` in the world; returns the instance index, which hits report
  // (hit_instance()).
  int add_instance(int mesh_index, const Eigen::Isometry3d& T_world_mesh);
  void set_instance_transform(int instance, const Eigen::Isometry3d& T_world_mesh);
  // Must be called after adding or moving instances, before tracing rays.
  void commit();

  // Nearest hits of up to 8 rays (valid[k] = -1) over every placed mesh, as rtcIntersect8:
  // tfar shortened and hit filled for the rays that hit. Coordinates are the world's shifted by
  // frame_y_mm along y (the point (x, y, z) of the rays is world (x, y + frame_y_mm, z)); hit
  // normals (Ng) are in the hit mesh's frame (world_normal()). Allocation-free.
  void intersect8(const int* valid, RTCRayHit8& rays, double frame_y_mm) const;
  // Occlusion of up to 8 rays, as rtcOccluded8 (tfar set to -inf when occluded), same frame.
  void occluded8(const int* valid, RTCRay8& rays, double frame_y_mm) const;

  // The hierarchy of mesh `mesh` in its own frame (std::invalid_argument when there is no
  // such mesh): its one geometry is never changed after add_mesh, so it may be queried
  // (rtcPointQuery) alongside the rays, or retained beyond the scene.
  RTCScene mesh_scene(int mesh) const;

  const Eigen::Isometry3d& instance_transform(int instance) const;
  // World bounding box of the instance's transformed vertices (tight, not a box of a box).
  const Eigen::AlignedBox3d& instance_bounds(int instance) const;
  // The instance a hit of intersect8 belongs to.
  static unsigned hit_instance(const RTCHit8& hit, int k) { return hit.instID[0][k]; }
  // Unit world normal from a hit's Ng (in the mesh's frame; the winding decides the sign,
  // which callers fix).
  Eigen::Vector3d world_normal(unsigned instance, float ng_x, float ng_y, float ng_z) const;

 private:
  struct Instance {
    int mesh = 0;
    Eigen::Isometry3d T_world_mesh = Eigen::Isometry3d::Identity();
    Eigen::Isometry3d T_mesh_world = Eigen::Isometry3d::Identity();
    Eigen::AlignedBox3d bounds;
  };

  void check(const char* operation) const;
  // Calls visit(index, instance, context) for each placement whose bounds meet the box the
  // valid rays sweep (their lengths capped), with one intersect context for the packet.
  template <class Visit>
  void for_each_instance_swept(const int* valid, const RTCRay8& rays, double frame_y_mm,
                               Visit&& visit) const;
  // Rays into the frame of `instance`: origins and directions carried in double.
  static void to_mesh_frame(const Instance& instance, const int* valid, const RTCRay8& world,
                            double frame_y_mm, RTCRay8& local);

  RTCDevice device_ = nullptr;
  std::vector<RTCScene> mesh_scenes_;  // per mesh, in its own frame
  std::vector<std::size_t> mesh_vertex_counts_;
  std::vector<Instance> instances_;
  BeltIntervalIndex instances_along_belt_;
};

}  // namespace cosmos
