#pragma once
// RAII over Embree 3 for the simulated scanner: one device, one scene, and two ways to place a
// mesh in it (T_world_mesh):
//   kBaked      the mesh's vertices are transformed and its triangles built straight into the
//               scene: the fastest rays (no instance transform per ray), but moving it
//               rebuilds the whole hierarchy.
//   kInstanced  the mesh is built once, in its own frame, as a bottom-level scene, and placed
//               by an Embree instance: moving it only recommits the top level, so a part turned
//               through the 320 model-view poses is never rebuilt.
//
// Determinism: the device runs one thread, so bounding-volume hierarchies are built the
// same way every run, and rays are traced by the caller in a fixed order. Embree's own
// thread pool would also compete with the other work of a two-core cell computer.
//
// Only .cpp files include this header: it brings in Embree's C API.
#include <embree3/rtcore.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "sim/mesh.hpp"

namespace cosmos {

enum class MeshPlacement : std::uint8_t { kBaked, kInstanced };

class EmbreeScene {
 public:
  EmbreeScene();
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Uploads a mesh (vertices in its own frame, mm) and returns its index. The mesh must
  // have at least one triangle with valid indices (std::invalid_argument otherwise).
  int add_mesh(const TriangleMesh& mesh);
  // Places mesh `mesh_index` in the world; returns the instance index, which is also the
  // Embree geometry ID of the placement (hit_instance() recovers it from a hit).
  int add_instance(int mesh_index, const Eigen::Isometry3d& T_world_mesh,
                   MeshPlacement placement = MeshPlacement::kBaked);
  void set_instance_transform(int instance, const Eigen::Isometry3d& T_world_mesh);
  // Must be called after adding or moving instances, before tracing rays.
  void commit();

  RTCScene handle() const { return top_; }
  const Eigen::Isometry3d& instance_transform(int instance) const;
  // World bounding box of the instance's transformed vertices (tight, not a box of a box).
  const Eigen::AlignedBox3d& instance_bounds(int instance) const;
  // The instance a hit belongs to, from its geomID and instID[0].
  static unsigned hit_instance(unsigned geometry_id, unsigned instance_id) {
    return instance_id != RTC_INVALID_GEOMETRY_ID ? instance_id : geometry_id;
  }
  // Unit world normal from a hit's Ng (Embree reports an instanced hit's normal in the mesh's
  // frame, a baked one's in the world; the winding decides the sign, which callers fix).
  Eigen::Vector3d world_normal(unsigned instance, float ng_x, float ng_y, float ng_z) const;

 private:
  struct Mesh {
    TriangleMesh mesh;
    RTCScene scene = nullptr;  // bottom-level scene, built on first instanced use
  };
  struct Instance {
    int mesh = 0;
    MeshPlacement placement = MeshPlacement::kBaked;
    RTCGeometry geometry = nullptr;
    Eigen::Isometry3d T_world_mesh = Eigen::Isometry3d::Identity();
    Eigen::AlignedBox3d bounds;
  };

  void check(const char* operation) const;
  RTCGeometry new_triangle_geometry(const TriangleMesh& mesh);
  RTCScene mesh_scene(int mesh_index);

  RTCDevice device_ = nullptr;
  RTCScene top_ = nullptr;
  std::vector<Mesh> meshes_;
  std::vector<Instance> instances_;
};

}  // namespace cosmos
