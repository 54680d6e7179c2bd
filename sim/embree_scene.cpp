#include "sim/embree_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/embree_triangle_geometry.hpp"

namespace cosmos {
namespace {

constexpr int kPacket = 8;
// A ray's sweep is boxed up to this length: the orthographic probe's rays are unbounded.
constexpr double kLongestRayMm = 1e6;

const char* error_name(RTCError error) {
  switch (error) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error";
  }
}

}  // namespace

EmbreeScene::EmbreeScene() {
  device_ = rtcNewDevice("threads=1,verbose=0");
  if (device_ == nullptr) {
    throw std::runtime_error(std::string("Embree: cannot create a device: ") +
                             error_name(rtcGetDeviceError(nullptr)));
  }
}

EmbreeScene::~EmbreeScene() {
  for (RTCScene scene : mesh_scenes_) rtcReleaseScene(scene);
  if (device_ != nullptr) rtcReleaseDevice(device_);
}

void EmbreeScene::check(const char* operation) const {
  const RTCError error = rtcGetDeviceError(device_);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + operation + ": " + error_name(error));
}

int EmbreeScene::add_mesh(const TriangleMesh& mesh) {
  RTCGeometry geometry = new_triangle_geometry(device_, mesh, "EmbreeScene::add_mesh");
  check("rtcSetNewGeometryBuffer");
  RTCScene scene = rtcNewScene(device_);
  // Watertight intersection: a ray through a shared edge or vertex of the tessellation must
  // hit one of the triangles, not slip through to the belt.
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  check("committing a mesh");
  mesh_scenes_.push_back(scene);
  mesh_vertex_counts_.push_back(mesh.vertices.size());
  return static_cast<int>(mesh_scenes_.size()) - 1;
}

RTCScene EmbreeScene::mesh_scene(int mesh) const {
  if (mesh < 0 || mesh >= static_cast<int>(mesh_scenes_.size()))
    throw std::invalid_argument("EmbreeScene::mesh_scene: no such mesh");
  return mesh_scenes_[static_cast<std::size_t>(mesh)];
}

int EmbreeScene::add_instance(int mesh_index, const Eigen::Isometry3d& T_world_mesh) {
  if (mesh_index < 0 || mesh_index >= static_cast<int>(mesh_scenes_.size())) {
    throw std::invalid_argument("EmbreeScene::add_instance: no such mesh");
  }
  Instance instance;
  instance.mesh = mesh_index;
  instances_.push_back(instance);
  const int index = static_cast<int>(instances_.size()) - 1;
  set_instance_transform(index, T_world_mesh);
  return index;
}

void EmbreeScene::set_instance_transform(int instance_index,
                                         const Eigen::Isometry3d& T_world_mesh) {
  Instance& instance = instances_.at(static_cast<std::size_t>(instance_index));
  instance.T_world_mesh = T_world_mesh;
  instance.T_mesh_world = T_world_mesh.inverse(Eigen::Isometry);
  instance.bounds.setEmpty();
  // The vertices as Embree keeps them (float x, y, z), the scene's only copy of its meshes.
  const auto mesh = static_cast<std::size_t>(instance.mesh);
  const float* vertices = triangle_buffers(mesh_scenes_[mesh]).vertices_mm;
  for (std::size_t v = 0; v < mesh_vertex_counts_[mesh]; ++v)
    instance.bounds.extend(
        T_world_mesh * Eigen::Vector3d(vertices[3 * v], vertices[3 * v + 1], vertices[3 * v + 2]));
}

void EmbreeScene::commit() {
  std::vector<Eigen::AlignedBox3d> boxes;
  boxes.reserve(instances_.size());
  for (const Instance& instance : instances_) boxes.push_back(instance.bounds);
  instances_along_belt_.rebuild(boxes);
}

template <class Visit>
void EmbreeScene::for_each_instance_swept(const int* valid, const RTCRay8& rays, double frame_y_mm,
                                          Visit&& visit) const {
  Eigen::AlignedBox3d box;
  for (int k = 0; k < kPacket; ++k) {
    if (valid[k] == 0 || !(rays.tfar[k] >= rays.tnear[k])) continue;
    const Eigen::Vector3d origin(rays.org_x[k], rays.org_y[k] + frame_y_mm, rays.org_z[k]);
    const Eigen::Vector3d direction(rays.dir_x[k], rays.dir_y[k], rays.dir_z[k]);
    const double far = std::min(static_cast<double>(rays.tfar[k]), kLongestRayMm);
    box.extend(origin + static_cast<double>(rays.tnear[k]) * direction);
    box.extend(origin + far * direction);
  }
  if (box.isEmpty()) return;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  instances_along_belt_.for_each_meeting(box.min().y(), box.max().y(), [&](int index) {
    const Instance& instance = instances_[static_cast<std::size_t>(index)];
    if (instance.bounds.intersects(box)) visit(index, instance, context);
  });
}

void EmbreeScene::to_mesh_frame(const Instance& instance, const int* valid, const RTCRay8& world,
                                double frame_y_mm, RTCRay8& local) {
  const Eigen::Matrix3d& R_mesh_world = instance.T_mesh_world.linear();
  for (int k = 0; k < kPacket; ++k) {
    local.tnear[k] = world.tnear[k];
    local.tfar[k] = world.tfar[k];
    local.time[k] = world.time[k];
    local.mask[k] = world.mask[k];
    local.id[k] = world.id[k];
    local.flags[k] = world.flags[k];
    if (valid[k] == 0) {
      local.org_x[k] = local.org_y[k] = local.org_z[k] = 0.0f;
      local.dir_x[k] = local.dir_y[k] = 0.0f;
      local.dir_z[k] = 1.0f;
      continue;
    }
    const Eigen::Vector3d origin =
        instance.T_mesh_world *
        Eigen::Vector3d(world.org_x[k], world.org_y[k] + frame_y_mm, world.org_z[k]);
    const Eigen::Vector3d direction =
        R_mesh_world * Eigen::Vector3d(world.dir_x[k], world.dir_y[k], world.dir_z[k]);
    local.org_x[k] = static_cast<float>(origin.x());
    local.org_y[k] = static_cast<float>(origin.y());
    local.org_z[k] = static_cast<float>(origin.z());
    local.dir_x[k] = static_cast<float>(direction.x());
    local.dir_y[k] = static_cast<float>(direction.y());
    local.dir_z[k] = static_cast<float>(direction.z());
  }
}

void EmbreeScene::intersect8(const int* valid, RTCRayHit8& rays, double frame_y_mm) const {
  for (int k = 0; k < kPacket; ++k) {
    rays.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
    rays.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
  }
  for_each_instance_swept(valid, rays.ray, frame_y_mm,
                          [&](int index, const Instance& instance, RTCIntersectContext& context) {
                            alignas(32) int local_valid[kPacket];
                            std::copy(valid, valid + kPacket, local_valid);
                            RTCRayHit8 local;
                            to_mesh_frame(instance, valid, rays.ray, frame_y_mm, local.ray);
                            for (int k = 0; k < kPacket; ++k) {
                              // The nearest hit so far bounds the ray: only a nearer one on this
                              // mesh replaces it.
                              local.ray.tfar[k] = rays.ray.tfar[k];
                              local.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                              local.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
                            }
                            rtcIntersect8(local_valid,
                                          mesh_scenes_[static_cast<std::size_t>(instance.mesh)],
                                          &context, &local);
                            for (int k = 0; k < kPacket; ++k) {
                              if (valid[k] == 0 || local.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID)
                                continue;
                              rays.ray.tfar[k] = local.ray.tfar[k];
                              rays.hit.Ng_x[k] = local.hit.Ng_x[k];
                              rays.hit.Ng_y[k] = local.hit.Ng_y[k];
                              rays.hit.Ng_z[k] = local.hit.Ng_z[k];
                              rays.hit.u[k] = local.hit.u[k];
                              rays.hit.v[k] = local.hit.v[k];
                              rays.hit.primID[k] = local.hit.primID[k];
                              rays.hit.geomID[k] = local.hit.geomID[k];
                              rays.hit.instID[0][k] = static_cast<unsigned>(index);
                            }
                          });
}

void EmbreeScene::occluded8(const int* valid, RTCRay8& rays, double frame_y_mm) const {
  for_each_instance_swept(
      valid, rays, frame_y_mm, [&](int, const Instance& instance, RTCIntersectContext& context) {
        alignas(32) int local_valid[kPacket];
        bool any = false;
        for (int k = 0; k < kPacket; ++k) {
          // A ray already occluded by another mesh needs no further test.
          local_valid[k] = valid[k] != 0 && rays.tfar[k] >= rays.tnear[k] ? -1 : 0;
          any = any || local_valid[k] != 0;
        }
        if (!any) return;
        RTCRay8 local;
        to_mesh_frame(instance, local_valid, rays, frame_y_mm, local);
        rtcOccluded8(local_valid, mesh_scenes_[static_cast<std::size_t>(instance.mesh)], &context,
                     &local);
        for (int k = 0; k < kPacket; ++k) {
          if (local_valid[k] != 0 && local.tfar[k] < 0.0f) rays.tfar[k] = local.tfar[k];
        }
      });
}

const Eigen::Isometry3d& EmbreeScene::instance_transform(int instance) const {
  return instances_.at(static_cast<std::size_t>(instance)).T_world_mesh;
}

const Eigen::AlignedBox3d& EmbreeScene::instance_bounds(int instance) const {
  return instances_.at(static_cast<std::size_t>(instance)).bounds;
}

Eigen::Vector3d EmbreeScene::world_normal(unsigned instance, float ng_x, float ng_y,
                                          float ng_z) const {
  const Instance& placed = instances_[instance];
  return (placed.T_world_mesh.linear() * Eigen::Vector3d(ng_x, ng_y, ng_z)).normalized();
}

}  // namespace cosmos
