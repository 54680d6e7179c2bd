#include "sim/assimp_mesh_reader.hpp"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <string>

#include "core/input_error.hpp"

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

void require_finite_vertices(const std::filesystem::path& path, const aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& part = *scene.mMeshes[m];
    for (unsigned v = 0; v < part.mNumVertices; ++v) {
      const aiVector3D& p = part.mVertices[v];
      if (const auto defect = vertex_defect({p.x, p.y, p.z})) fail(path, "vertex " + *defect);
    }
  }
}

}  // namespace

TriangleMesh read_assimp_mesh(const std::filesystem::path& path) {
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
  return mesh;
}

}  // namespace cosmos
