// Parts built in code (procedural_parts.hpp): closed, outward-wound solids of the volume their
// outline or profile gives, the same for the same seed, and readable back from their OFF file.
#include "sim/procedural_parts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

namespace cosmos {
namespace {

// Signed volume by the divergence theorem: positive when every face is wound outward.
double signed_volume(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[static_cast<std::size_t>(t[0])].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[static_cast<std::size_t>(t[1])].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[static_cast<std::size_t>(t[2])].cast<double>();
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

// Every directed edge once, and its reverse once: closed and consistently wound.
int unmatched_edges(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const Eigen::Vector3i& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  int unmatched = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++unmatched;
  }
  return unmatched;
}

TEST(ProceduralParts, AnExtrudedLShapeIsClosedWithItsPrismVolume) {
  const std::vector<Eigen::Vector2d> l_shape = {{0, 0},   {50, 0},  {50, 10},
                                                {10, 10}, {10, 40}, {0, 40}};
  const TriangleMesh prism = make_extrusion(l_shape, 20.0);
  EXPECT_EQ(prism.vertices.size(), 12u);
  EXPECT_EQ(prism.triangles.size(), 2u * 4 + 2u * 6);
  EXPECT_EQ(unmatched_edges(prism), 0);
  EXPECT_NEAR(signed_volume(prism), (50.0 * 10 + 10.0 * 30) * 20.0, 1e-3);
}

TEST(ProceduralParts, ClockwiseOrDegenerateOutlinesAreRefused) {
  const std::vector<Eigen::Vector2d> clockwise = {{0, 0}, {0, 10}, {10, 10}, {10, 0}};
  EXPECT_THROW(make_extrusion(clockwise, 5.0), std::invalid_argument);
  const std::vector<Eigen::Vector2d> line = {{0, 0}, {10, 0}, {20, 0}};
  EXPECT_THROW(make_extrusion(line, 5.0), std::invalid_argument);
  const std::vector<Eigen::Vector2d> square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_THROW(make_extrusion(square, 0.0), std::invalid_argument);
}

TEST(ProceduralParts, ASteppedRevolutionIsClosedWithItsCylindersVolume) {
  const int segments = 96;
  const std::vector<Eigen::Vector2d> profile = {{0, 0},  {20, 0}, {20, 15},
                                                {8, 15}, {8, 45}, {0, 45}};
  const TriangleMesh shaft = make_revolution(profile, segments);
  EXPECT_EQ(unmatched_edges(shaft), 0);
  // The inscribed polygon's area is (n / 2) sin(2 pi / n) r^2 instead of pi r^2.
  const double polygon_factor =
      segments / 2.0 * std::sin(2.0 * std::numbers::pi / segments) / std::numbers::pi;
  const double volume = std::numbers::pi * (20.0 * 20.0 * 15.0 + 8.0 * 8.0 * 30.0) * polygon_factor;
  EXPECT_NEAR(signed_volume(shaft), volume, 1e-3 * volume);
  const std::vector<Eigen::Vector2d> off_axis = {{1, 0}, {20, 0}, {0, 10}};
  EXPECT_THROW(make_revolution(off_axis, segments), std::invalid_argument);
}

TEST(ProceduralParts, EveryFamilyGivesClosedDistinctPartsFixedBySeed) {
  const std::vector<ProceduralPart> parts = procedural_parts(3, 1);
  ASSERT_EQ(parts.size(), 3u * procedural_families().size());
  std::set<std::string> names;
  for (const ProceduralPart& part : parts) {
    names.insert(part.name);
    EXPECT_EQ(unmatched_edges(part.mesh), 0) << part.name;
    EXPECT_GT(signed_volume(part.mesh), 0.0) << part.name;
  }
  EXPECT_EQ(names.size(), parts.size());
  const std::vector<ProceduralPart> again = procedural_parts(3, 1);
  const std::vector<ProceduralPart> other = procedural_parts(3, 2);
  int differing = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    EXPECT_EQ(again[i].mesh.vertices, parts[i].mesh.vertices) << parts[i].name;
    differing += other[i].mesh.vertices != parts[i].mesh.vertices ? 1 : 0;
  }
  EXPECT_EQ(differing, static_cast<int>(parts.size()));
}

TEST(ProceduralParts, TheOffFileReadsBackAsTheSameMesh) {
  const ProceduralPart part = procedural_parts(1, 7).front();
  const std::filesystem::path file =
      std::filesystem::path(testing::TempDir()) / ("procedural-" + part.name + ".off");
  write_off_file(part.mesh, file);
  const TriangleMesh read = read_mesh_file(file);
  EXPECT_EQ(read.triangles.size(), part.mesh.triangles.size());
  EXPECT_EQ(read.vertices.size(), part.mesh.vertices.size());
  EXPECT_NEAR(signed_volume(read), signed_volume(part.mesh), 1e-3 * signed_volume(part.mesh));
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace cosmos
