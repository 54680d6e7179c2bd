#include "sim/embree_scene.hpp"

#include <stdexcept>
#include <string>

namespace cosmos {
namespace {

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

void set_instance_matrix(RTCGeometry geometry, const Eigen::Isometry3d& T_world_mesh) {
  // Embree's RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR: the 3x3 linear part column by column, then the
  // translation.
  float matrix[12];
  const Eigen::Matrix3d& R = T_world_mesh.linear();
  const Eigen::Vector3d& t = T_world_mesh.translation();
  for (int column = 0; column < 3; ++column) {
    for (int row = 0; row < 3; ++row) matrix[column * 3 + row] = static_cast<float>(R(row, column));
  }
  for (int row = 0; row < 3; ++row) matrix[9 + row] = static_cast<float>(t(row));
  rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, matrix);
}

void write_vertices(RTCGeometry geometry, const TriangleMesh& mesh,
                    const Eigen::Isometry3d& T_world_mesh) {
  auto* vertices =
      static_cast<float*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, 0));
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3d world = T_world_mesh * mesh.vertices[v].cast<double>();
    for (int k = 0; k < 3; ++k)
      vertices[3 * v + static_cast<std::size_t>(k)] = static_cast<float>(world(k));
  }
}

}  // namespace

EmbreeScene::EmbreeScene() {
  device_ = rtcNewDevice("threads=1,verbose=0");
  if (device_ == nullptr) {
    throw std::runtime_error(std::string("Embree: cannot create a device: ") +
                             error_name(rtcGetDeviceError(nullptr)));
  }
  top_ = rtcNewScene(device_);
  // Watertight intersection: a ray through a shared edge or vertex of the tessellation must
  // hit one of the triangles, not slip through to the belt.
  rtcSetSceneFlags(top_, RTC_SCENE_FLAG_ROBUST);
  check("rtcNewScene");
}

EmbreeScene::~EmbreeScene() {
  for (Instance& instance : instances_) rtcReleaseGeometry(instance.geometry);
  for (Mesh& mesh : meshes_) {
    if (mesh.scene != nullptr) rtcReleaseScene(mesh.scene);
  }
  if (top_ != nullptr) rtcReleaseScene(top_);
  if (device_ != nullptr) rtcReleaseDevice(device_);
}

void EmbreeScene::check(const char* operation) const {
  const RTCError error = rtcGetDeviceError(device_);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + operation + ": " + error_name(error));
}

int EmbreeScene::add_mesh(const TriangleMesh& mesh) {
  if (mesh.triangles.empty())
    throw std::invalid_argument("EmbreeScene::add_mesh: mesh has no triangles");
  const auto vertex_count = static_cast<int>(mesh.vertices.size());
  for (const Eigen::Vector3i& triangle : mesh.triangles) {
    if (triangle.minCoeff() < 0 || triangle.maxCoeff() >= vertex_count) {
      throw std::invalid_argument("EmbreeScene::add_mesh: triangle index out of range");
    }
  }
  meshes_.push_back({mesh, nullptr});
  return static_cast<int>(meshes_.size()) - 1;
}

RTCGeometry EmbreeScene::new_triangle_geometry(const TriangleMesh& mesh) {
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  // rtcSetNewGeometryBuffer pads the buffers as Embree's vector loads require.
  rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                          mesh.vertices.size());
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), mesh.triangles.size()));
  check("rtcSetNewGeometryBuffer");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k)
      indices[3 * t + static_cast<std::size_t>(k)] = static_cast<unsigned>(mesh.triangles[t](k));
  }
  return geometry;
}

RTCScene EmbreeScene::mesh_scene(int mesh_index) {
  Mesh& mesh = meshes_[static_cast<std::size_t>(mesh_index)];
  if (mesh.scene != nullptr) return mesh.scene;
  RTCGeometry geometry = new_triangle_geometry(mesh.mesh);
  write_vertices(geometry, mesh.mesh, Eigen::Isometry3d::Identity());
  rtcCommitGeometry(geometry);
  mesh.scene = rtcNewScene(device_);
  rtcSetSceneFlags(mesh.scene, RTC_SCENE_FLAG_ROBUST);
  rtcAttachGeometry(mesh.scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(mesh.scene);
  check("committing a mesh");
  return mesh.scene;
}

int EmbreeScene::add_instance(int mesh_index, const Eigen::Isometry3d& T_world_mesh,
                              MeshPlacement placement) {
  if (mesh_index < 0 || mesh_index >= static_cast<int>(meshes_.size())) {
    throw std::invalid_argument("EmbreeScene::add_instance: no such mesh");
  }
  Instance instance;
  instance.mesh = mesh_index;
  instance.placement = placement;
  if (placement == MeshPlacement::kInstanced) {
    instance.geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(instance.geometry, mesh_scene(mesh_index));
  } else {
    instance.geometry = new_triangle_geometry(meshes_[static_cast<std::size_t>(mesh_index)].mesh);
  }
  const unsigned id = rtcAttachGeometry(top_, instance.geometry);
  check("adding an instance");
  if (id != instances_.size()) throw std::logic_error("EmbreeScene: geometry ids out of step");
  instances_.push_back(instance);
  set_instance_transform(static_cast<int>(id), T_world_mesh);
  return static_cast<int>(id);
}

void EmbreeScene::set_instance_transform(int instance_index,
                                         const Eigen::Isometry3d& T_world_mesh) {
  Instance& instance = instances_.at(static_cast<std::size_t>(instance_index));
  const TriangleMesh& mesh = meshes_[static_cast<std::size_t>(instance.mesh)].mesh;
  instance.T_world_mesh = T_world_mesh;
  if (instance.placement == MeshPlacement::kInstanced) {
    set_instance_matrix(instance.geometry, T_world_mesh);
  } else {
    write_vertices(instance.geometry, mesh, T_world_mesh);
    rtcUpdateGeometryBuffer(instance.geometry, RTC_BUFFER_TYPE_VERTEX, 0);
  }
  rtcCommitGeometry(instance.geometry);
  instance.bounds.setEmpty();
  for (const Eigen::Vector3f& vertex : mesh.vertices)
    instance.bounds.extend(T_world_mesh * vertex.cast<double>());
  check("moving an instance");
}

void EmbreeScene::commit() {
  rtcCommitScene(top_);
  check("rtcCommitScene");
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
  const Eigen::Vector3d normal(ng_x, ng_y, ng_z);
  if (placed.placement == MeshPlacement::kBaked) return normal.normalized();
  return (placed.T_world_mesh.linear() * normal).normalized();
}

}  // namespace cosmos
