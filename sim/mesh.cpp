#include "sim/mesh.hpp"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/input_error.hpp"
#include "sim/mesh_element_counts.hpp"

namespace cosmos {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
  throw InputError(path.string() + ": " + reason);
}

// Assimp's messages can span lines; the project's error contract is one line.
std::string one_line(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  text.erase(
      std::unique(text.begin(), text.end(), [](char a, char b) { return a == ' ' && b == ' '; }),
      text.end());
  const auto first = text.find_first_not_of(' ');
  const auto last = text.find_last_not_of(' ');
  return first == std::string::npos ? std::string{} : text.substr(first, last - first + 1);
}

std::string lowercase_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// Assimp can guess formats from content, but the design fixes the four formats the catalog
// is tested with; anything else is refused before assimp sees it, with a clear reason.
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

void append_scene_meshes(const aiScene& scene, TriangleMesh& mesh) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& part = *scene.mMeshes[m];
    if ((part.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    const int offset = static_cast<int>(mesh.vertices.size());
    for (unsigned v = 0; v < part.mNumVertices; ++v) {
      const aiVector3D& p = part.mVertices[v];
      mesh.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < part.mNumFaces; ++f) {
      const aiFace& face = part.mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.emplace_back(offset + static_cast<int>(face.mIndices[0]),
                                  offset + static_cast<int>(face.mIndices[1]),
                                  offset + static_cast<int>(face.mIndices[2]));
    }
  }
}

// A stray vertex that no triangle uses would still stretch the bounding box and so shrink
// the part at scaling; only the surface counts.
void remove_unreferenced_vertices(TriangleMesh& mesh) {
  std::vector<int> new_index(mesh.vertices.size(), -1);
  std::vector<Eigen::Vector3f> kept;
  kept.reserve(mesh.vertices.size());
  for (Eigen::Vector3i& triangle : mesh.triangles) {
    for (int corner = 0; corner < 3; ++corner) {
      int& index = new_index[static_cast<std::size_t>(triangle[corner])];
      if (index < 0) {
        index = static_cast<int>(kept.size());
        kept.push_back(mesh.vertices[static_cast<std::size_t>(triangle[corner])]);
      }
      triangle[corner] = index;
    }
  }
  mesh.vertices = std::move(kept);
}

void require_finite_vertices(const std::filesystem::path& path, const aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& part = *scene.mMeshes[m];
    for (unsigned v = 0; v < part.mNumVertices; ++v) {
      const aiVector3D& p = part.mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        std::ostringstream reason;
        reason << "vertex (" << p.x << ", " << p.y << ", " << p.z
               << ") has a NaN or infinite coordinate";
        fail(path, reason.str());
      }
    }
  }
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

TriangleMesh read_mesh_file(const std::filesystem::path& path) {
  check_file(path);
  check_mesh_element_counts(path);
  Assimp::Importer importer;
  // Points and lines carry no surface to scan; sorting by primitive type and removing them
  // leaves only triangles after triangulation.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // Only positions are used. Dropping the other vertex components first lets
  // JoinIdenticalVertices weld by position alone: STL repeats each corner per face with the
  // face normal, which would otherwise keep every triangle's corners apart.
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
                              aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS |
                                  aiComponent_COLORS | aiComponent_TEXCOORDS |
                                  aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS |
                                  aiComponent_TEXTURES | aiComponent_LIGHTS | aiComponent_CAMERAS);
  const auto assimp_failure = [&] {
    const std::string reason = one_line(importer.GetErrorString());
    fail(path,
         "assimp cannot read it: " + (reason.empty() ? std::string("unknown error") : reason));
  };
  // Read raw first: JoinIdenticalVertices silently drops a NaN vertex (it never compares
  // equal) and rewires its faces, so non-finite coordinates must be caught before it runs.
  const aiScene* scene = importer.ReadFile(path.string(), 0);
  if (scene == nullptr) assimp_failure();
  require_finite_vertices(path, *scene);
  scene = importer.ApplyPostProcessing(
      aiProcess_RemoveComponent | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
      aiProcess_SortByPType | aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure);
  if (scene == nullptr) assimp_failure();
  TriangleMesh mesh;
  append_scene_meshes(*scene, mesh);
  remove_unreferenced_vertices(mesh);
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
