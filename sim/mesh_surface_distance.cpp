#include "sim/mesh_surface_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/embree_scene.hpp"
#include "sim/embree_triangle_geometry.hpp"

namespace cosmos {
namespace {

double point_segment_squared_distance(const Eigen::Vector3d& point, const Eigen::Vector3d& a,
                                      const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((point - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - point).squaredNorm();
}

}  // namespace

double point_triangle_squared_distance(const Eigen::Vector3d& point, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a;
  if (ab.cross(ac).squaredNorm() <= 1e-24 * ab.squaredNorm() * ac.squaredNorm())
    return std::min({point_segment_squared_distance(point, a, b),
                     point_segment_squared_distance(point, b, c),
                     point_segment_squared_distance(point, c, a)});
  // The Voronoi regions of the vertices, then of the edges, then the face.
  const Eigen::Vector3d ap = point - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3d bp = point - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (a + (d1 / (d1 - d3)) * ab - point).squaredNorm();
  const Eigen::Vector3d cp = point - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (a + (d2 / (d2 - d6)) * ac - point).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b) - point).squaredNorm();
  const double denominator = va + vb + vc;
  return (a + (vb / denominator) * ab + (vc / denominator) * ac - point).squaredNorm();
}

// A retained reference to a scene holding one triangle geometry, and that geometry's
// buffers (Embree keeps them as long as the scene).
struct MeshSurfaceDistance::Hierarchy {
  RTCScene scene = nullptr;
  TriangleBuffers buffers;

  explicit Hierarchy(RTCScene mesh_scene) : scene(mesh_scene), buffers(triangle_buffers(scene)) {
    rtcRetainScene(scene);
  }
  ~Hierarchy() { rtcReleaseScene(scene); }
  Hierarchy(const Hierarchy&) = delete;
  Hierarchy& operator=(const Hierarchy&) = delete;
};

namespace {

constexpr double kRadiusMarginMm = 1e-3;

struct NearestQuery {
  const float* vertices_mm;
  const unsigned* triangles;
  Eigen::Vector3d point_mm;
  double best_mm2;
};

bool measure_triangle(RTCPointQueryFunctionArguments* args) {
  auto& query = *static_cast<NearestQuery*>(args->userPtr);
  const unsigned* triangle = query.triangles + 3 * static_cast<std::size_t>(args->primID);
  const auto vertex = [&query](unsigned index) {
    const float* v = query.vertices_mm + 3 * static_cast<std::size_t>(index);
    return Eigen::Vector3d(v[0], v[1], v[2]);
  };
  const double d2 = point_triangle_squared_distance(query.point_mm, vertex(triangle[0]),
                                                    vertex(triangle[1]), vertex(triangle[2]));
  if (d2 >= query.best_mm2) return false;
  query.best_mm2 = d2;
  // With a margin over the float rounding of the query's point and radius, so the walk never
  // prunes a triangle nearer than the double distance.
  args->query->radius = static_cast<float>(std::sqrt(d2) + kRadiusMarginMm);
  return true;
}

}  // namespace

// A scene of its own, kept only for the hierarchy it builds: the hierarchy outlives it.
MeshSurfaceDistance::MeshSurfaceDistance(const TriangleMesh& mesh) {
  EmbreeScene scene;
  hierarchy_ = std::make_unique<Hierarchy>(scene.mesh_scene(scene.add_mesh(mesh)));
}

MeshSurfaceDistance::MeshSurfaceDistance(const EmbreeScene& scene, int mesh)
    : hierarchy_(std::make_unique<Hierarchy>(scene.mesh_scene(mesh))) {}

MeshSurfaceDistance::~MeshSurfaceDistance() = default;

double MeshSurfaceDistance::nearest_squared_mm2(const Eigen::Vector3d& point_mm) const {
  NearestQuery nearest{hierarchy_->buffers.vertices_mm, hierarchy_->buffers.triangles, point_mm,
                       std::numeric_limits<double>::infinity()};
  RTCPointQuery query;
  query.x = static_cast<float>(point_mm.x());
  query.y = static_cast<float>(point_mm.y());
  query.z = static_cast<float>(point_mm.z());
  query.time = 0.0f;
  query.radius = std::numeric_limits<float>::infinity();
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(hierarchy_->scene, &query, &context, measure_triangle, &nearest);
  return nearest.best_mm2;
}

}  // namespace cosmos
