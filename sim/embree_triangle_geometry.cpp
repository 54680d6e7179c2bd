#include "sim/embree_triangle_geometry.hpp"

#include <stdexcept>
#include <string>

namespace cosmos {

RTCGeometry new_triangle_geometry(RTCDevice device, const TriangleMesh& mesh, const char* who) {
  if (mesh.triangles.empty())
    throw std::invalid_argument(std::string(who) + ": mesh has no triangles");
  const auto vertex_count = static_cast<int>(mesh.vertices.size());
  for (const Eigen::Vector3i& triangle : mesh.triangles)
    if (triangle.minCoeff() < 0 || triangle.maxCoeff() >= vertex_count)
      throw std::invalid_argument(std::string(who) + ": triangle index out of range");
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.vertices.size()));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), mesh.triangles.size()));
  if (vertices == nullptr || indices == nullptr) {
    rtcReleaseGeometry(geometry);
    throw std::runtime_error(std::string(who) + ": Embree cannot allocate the mesh's buffers");
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (int k = 0; k < 3; ++k) vertices[3 * v + static_cast<std::size_t>(k)] = mesh.vertices[v](k);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      indices[3 * t + static_cast<std::size_t>(k)] = static_cast<unsigned>(mesh.triangles[t](k));
  rtcCommitGeometry(geometry);
  return geometry;
}

TriangleBuffers triangle_buffers(RTCScene scene) {
  RTCGeometry geometry = rtcGetGeometry(scene, 0);
  return {
      static_cast<const float*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, 0)),
      static_cast<const unsigned*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_INDEX, 0))};
}

}  // namespace cosmos
