// The project's OFF and PLY readers against assimp's on every OFF and PLY mesh of the fetched
// catalog cache: each file loads with the vertex and triangle counts and the bounding box
// assimp read it with before the project had its own readers (or both refuse it), except the
// files assimp misreads, where the triangles are the ones the file declares.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <set>
#include <string>

#include "core/input_error.hpp"
#include "sim/assimp_mesh_reader.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// Assimp's triangles over the vertices they use, as read_mesh_file keeps them.
struct MeshSummary {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  Eigen::AlignedBox3f box;
};

MeshSummary summary_of_assimp(const fs::path& path) {
  const TriangleMesh mesh = read_assimp_mesh(path);
  std::set<int> used;
  MeshSummary summary;
  for (const Eigen::Vector3i& triangle : mesh.triangles)
    for (int corner = 0; corner < 3; ++corner) {
      used.insert(triangle[corner]);
      summary.box.extend(mesh.vertices[static_cast<std::size_t>(triangle[corner])]);
    }
  summary.vertices = used.size();
  summary.triangles = mesh.triangles.size();
  return summary;
}

// Files assimp reads otherwise than the format says, and their triangles counted by hand from
// the file (a face of n corners is n - 2 triangles).
struct AssimpMisreading {
  const char* file;
  std::size_t triangles;
  const char* why;
};
constexpr const char* kBlankLines =
    "blank or comment lines between the data lines, which assimp reads as a vertex or a face";
const AssimpMisreading kAssimpMisreadings[] = {
    {"blobby-shuffled.off", 4050, kBlankLines},
    {"cube-shuffled.off", 12, kBlankLines},
    {"cube4-shuffled.off", 12, kBlankLines},
    {"cube_poly.off", 12, kBlankLines},
    {"mpi_triang.off", 180, kBlankLines},
    {"oblong-shuffled.off", 840, kBlankLines},
    {"prim.off", 12, kBlankLines},
    {"sphere966.off", 1848, kBlankLines},
    {"mpi.off", 180, "faces of 10 corners, which assimp drops (it takes at most 9)"},
    {"mesh_with_colors.off", 6, "a pentagon among triangles with colours, which assimp refuses"},
};

const AssimpMisreading* misreading_of(const fs::path& path) {
  for (const AssimpMisreading& misreading : kAssimpMisreadings)
    if (path.filename() == misreading.file) return &misreading;
  return nullptr;
}

// Assimp's number parser is not correctly rounded: its coordinates may be a float step off.
bool same_box(const Eigen::AlignedBox3f& a, const Eigen::AlignedBox3f& b) {
  const float step = 2e-7f * std::max(a.sizes().maxCoeff(), 1.0f);
  return (a.min() - b.min()).cwiseAbs().maxCoeff() <= step &&
         (a.max() - b.max()).cwiseAbs().maxCoeff() <= step;
}

TEST(CatalogMeshReaders, EveryOffAndPlyMeshLoadsAsAssimpReadsIt) {
  const fs::path cache = default_mesh_cache_dir();
  ASSERT_TRUE(fs::is_directory(cache))
      << "the mesh cache " << cache
      << " is missing: run scripts/fetch_catalog.sh (or scripts/setup.sh)";
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(cache)) {
    const std::string extension = entry.path().extension().string();
    if (extension == ".off" || extension == ".ply") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 100u);
  int compared = 0, misread = 0;
  for (const fs::path& path : files) {
    SCOPED_TRACE(path.filename().string());
    if (const AssimpMisreading* misreading = misreading_of(path)) {
      EXPECT_EQ(read_mesh_file(path).triangles.size(), misreading->triangles) << misreading->why;
      ++misread;
      continue;
    }
    std::string ours_error, assimp_error;
    TriangleMesh ours;
    MeshSummary theirs;
    try {
      ours = read_mesh_file(path);
    } catch (const InputError& error) {
      ours_error = error.what();
    }
    try {
      theirs = summary_of_assimp(path);
      if (theirs.triangles == 0) assimp_error = "no triangles";
    } catch (const InputError& error) {
      assimp_error = error.what();
    }
    EXPECT_EQ(ours_error.empty(), assimp_error.empty())
        << "ours: '" << ours_error << "', assimp: '" << assimp_error << "'";
    if (!ours_error.empty() || !assimp_error.empty()) {
      std::cout << "[ refused  ] " << path.filename().string() << ": " << ours_error << "\n";
      continue;
    }
    ++compared;
    EXPECT_EQ(ours.vertices.size(), theirs.vertices);
    EXPECT_EQ(ours.triangles.size(), theirs.triangles);
    const Eigen::AlignedBox3f box = bounding_box(ours);
    EXPECT_TRUE(same_box(box, theirs.box))
        << "ours " << box.min().transpose() << " .. " << box.max().transpose() << ", assimp "
        << theirs.box.min().transpose() << " .. " << theirs.box.max().transpose();
  }
  std::cout << "[ compared ] " << compared << " of " << files.size() << " OFF and PLY files; "
            << misread << " that assimp misreads\n";
  EXPECT_EQ(misread, static_cast<int>(std::size(kAssimpMisreadings)));
}

}  // namespace
}  // namespace cosmos
