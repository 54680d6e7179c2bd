#include "sim/mesh.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "core/input_error.hpp"
#include "sim/obj_mesh_reader.hpp"
#include "sim/off_mesh_reader.hpp"
#include "sim/ply_mesh_reader.hpp"
#include "sim/stl_mesh_reader.hpp"

namespace cosmos {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
  throw InputError(path.string() + ": " + reason);
}

std::string lowercase_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// The four formats the catalog is tested with; anything else is refused before any reader
// sees it, with a clear reason.
void check_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) fail(path, "mesh file not found");
  if (!std::filesystem::is_regular_file(path, error)) fail(path, "not a regular file");
  const std::string extension = lowercase_extension(path);
  if (extension != ".off" && extension != ".ply" && extension != ".stl" && extension != ".obj") {
    fail(path, "unknown mesh extension '" + path.extension().string() +
                   "' (expected .off, .ply, .stl or .obj)");
  }
}

// Joins vertices at the same position (the readers keep a file's duplicates, and STL repeats
// every corner) and drops the ones no triangle uses: a stray vertex would still stretch the
// bounding box and so shrink the part at scaling. Vertices keep the order of their first use.
void compact_vertices(TriangleMesh& mesh) {
  const auto less = [&](int a, int b) {
    const Eigen::Vector3f& p = mesh.vertices[static_cast<std::size_t>(a)];
    const Eigen::Vector3f& q = mesh.vertices[static_cast<std::size_t>(b)];
    return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
  };
  std::vector<int> by_position(mesh.vertices.size());
  std::iota(by_position.begin(), by_position.end(), 0);
  std::stable_sort(by_position.begin(), by_position.end(), less);
  std::vector<int> same_as(mesh.vertices.size());  // the first vertex at each one's position
  for (std::size_t k = 0; k < by_position.size(); ++k) {
    const int vertex = by_position[k];
    same_as[static_cast<std::size_t>(vertex)] =
        k > 0 && !less(by_position[k - 1], vertex)
            ? same_as[static_cast<std::size_t>(by_position[k - 1])]
            : vertex;
  }
  std::vector<int> new_index(mesh.vertices.size(), -1);
  std::vector<Eigen::Vector3f> kept;
  kept.reserve(mesh.vertices.size());
  for (Eigen::Vector3i& triangle : mesh.triangles) {
    for (int corner = 0; corner < 3; ++corner) {
      const int vertex = same_as[static_cast<std::size_t>(triangle[corner])];
      int& index = new_index[static_cast<std::size_t>(vertex)];
      if (index < 0) {
        index = static_cast<int>(kept.size());
        kept.push_back(mesh.vertices[static_cast<std::size_t>(vertex)]);
      }
      triangle[corner] = index;
    }
  }
  mesh.vertices = std::move(kept);
}

void validate(const std::filesystem::path& path, const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) fail(path, "mesh has no triangles");
  const Eigen::Vector3f extent = bounding_box(mesh).sizes();
  if (!(extent.maxCoeff() > 0.0f))
    fail(path, "degenerate mesh: all vertices at one point (zero size)");
}

}  // namespace

Eigen::AlignedBox3f bounding_box(const TriangleMesh& mesh) {
  Eigen::AlignedBox3f box;  // Eigen's default box is empty, so extend() starts clean
  for (const Eigen::Vector3f& vertex : mesh.vertices) box.extend(vertex);
  return box;
}

std::optional<std::string> vertex_defect(const Eigen::Vector3f& vertex) {
  if (vertex.allFinite()) return std::nullopt;
  std::ostringstream reason;
  reason << "(" << vertex.x() << ", " << vertex.y() << ", " << vertex.z()
         << ") has a NaN or infinite coordinate";
  return reason.str();
}

TriangleMesh read_mesh_file(const std::filesystem::path& path) {
  check_file(path);
  const std::string extension = lowercase_extension(path);
  TriangleMesh mesh = extension == ".off"   ? triangulate(read_off_mesh(path))
                      : extension == ".ply" ? triangulate(read_ply_mesh(path))
                      : extension == ".obj" ? triangulate(read_obj_mesh(path))
                                            : read_stl_mesh(path);
  compact_vertices(mesh);
  validate(path, mesh);
  return mesh;
}

void center_and_scale(TriangleMesh& mesh, double size_mm) {
  const Eigen::AlignedBox3f box = bounding_box(mesh);
  const double extent = mesh.vertices.empty() ? 0.0 : static_cast<double>(box.sizes().maxCoeff());
  if (!(extent > 0.0) || !std::isfinite(extent)) {
    throw std::invalid_argument("center_and_scale: mesh has no positive finite extent");
  }
  if (!(size_mm > 0.0) || !std::isfinite(size_mm)) {
    throw std::invalid_argument("center_and_scale: size_mm must be finite and > 0");
  }
  // Scaling in double keeps the largest extent within float rounding of size_mm.
  const Eigen::Vector3d centre = box.center().cast<double>();
  const double scale = size_mm / extent;
  for (Eigen::Vector3f& vertex : mesh.vertices) {
    vertex = ((vertex.cast<double>() - centre) * scale).cast<float>();
  }
}

TriangleMesh load_mesh(const std::filesystem::path& path, double size_mm) {
  if (!(size_mm > 0.0) || !std::isfinite(size_mm)) {
    std::ostringstream reason;
    reason << "size_mm must be finite and > 0 (got " << size_mm << ")";
    fail(path, reason.str());
  }
  TriangleMesh mesh = read_mesh_file(path);
  center_and_scale(mesh, size_mm);
  return mesh;
}

}  // namespace cosmos
