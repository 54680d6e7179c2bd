// The STL reader: binary and ASCII files of one solid read to the same welded triangles, a
// binary header starting with "solid" is still binary, and each malformed file is refused on
// one line naming the file and its line (ASCII) or byte (binary).
#include "sim/stl_mesh_reader.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "tests/sim/mesh_file_fixture.hpp"

namespace cosmos {
namespace {

class StlMeshReader : public MeshFileFixture {
 protected:
  std::string read_error(const std::string& text) const {
    const auto path = write("bad.stl", text);
    return after_file_name(path, [&] { read_stl_mesh(path); });
  }
};

// The unit cube's 8 corners and its 12 triangles (two per face, outward winding): an STL file
// holds 36 corners, which weld back to the 8.
const float kCorners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const int kTriangles[12][3] = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                               {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};

std::string ascii_cube(const std::string& keyword_case_of_facet = "facet") {
  std::string text = "solid unit cube\n";
  for (const auto& triangle : kTriangles) {
    text += "  " + keyword_case_of_facet + " normal 0 0 0\n    outer loop\n";
    for (int corner : triangle) {
      const float* p = kCorners[corner];
      text += "      vertex " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " +
              std::to_string(p[2]) + "\n";
    }
    text += "    endloop\n  endfacet\n";
  }
  return text + "endsolid unit cube\n";
}

void append_float(std::string& out, float value) {
  char bytes[4];
  std::memcpy(bytes, &value, 4);
  out.append(bytes, 4);
}

// The cube as a binary file; `header` fills the 80 header bytes, `count` overrides the count.
std::string binary_cube(const std::string& header = "binary cube", std::uint32_t count = 12) {
  std::string out = header;
  out.resize(80, ' ');
  out.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& triangle : kTriangles) {
    for (int axis = 0; axis < 3; ++axis) append_float(out, 0.0f);  // normal
    for (int corner : triangle)
      for (int axis = 0; axis < 3; ++axis) append_float(out, kCorners[corner][axis]);
    out.append(2, '\0');
  }
  return out;
}

void expect_cube(const TriangleMesh& mesh) {
  ASSERT_EQ(mesh.vertices.size(), 8u);
  ASSERT_EQ(mesh.triangles.size(), 12u);
  // Vertices in the order of their first use: 0, 3, 2 of the first triangle, then 1.
  EXPECT_EQ(mesh.vertices[0], Eigen::Vector3f(0, 0, 0));
  EXPECT_EQ(mesh.vertices[1], Eigen::Vector3f(0, 1, 0));
  EXPECT_EQ(mesh.vertices[2], Eigen::Vector3f(1, 1, 0));
  EXPECT_EQ(mesh.vertices[3], Eigen::Vector3f(1, 0, 0));
  for (int t = 0; t < 12; ++t)
    for (int corner = 0; corner < 3; ++corner)
      EXPECT_EQ(
          mesh.vertices[static_cast<std::size_t>(mesh.triangles[t][corner])],
          Eigen::Vector3f(kCorners[kTriangles[t][corner]][0], kCorners[kTriangles[t][corner]][1],
                          kCorners[kTriangles[t][corner]][2]))
          << "triangle " << t << " corner " << corner;
}

TEST_F(StlMeshReader, AsciiCubeCornersWeldToItsEightVertices) {
  expect_cube(read_stl_mesh(write("cube.stl", ascii_cube())));
}

TEST_F(StlMeshReader, BinaryCubeCornersWeldToItsEightVertices) {
  expect_cube(read_stl_mesh(write("cube.stl", binary_cube())));
}

// Some exporters begin a binary header with "solid": the size, exactly 84 + 50 per triangle,
// decides, as it does for common readers.
TEST_F(StlMeshReader, BinaryHeaderStartingWithSolidIsReadAsBinary) {
  expect_cube(read_stl_mesh(write("solid.stl", binary_cube("solid cube, binary"))));
}

TEST_F(StlMeshReader, KeywordsInAnyCaseCrlfAndSeveralSolidsAreRead) {
  std::string text = ascii_cube("FACET");
  for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 2))
    text.replace(at, 1, "\r\n");
  expect_cube(read_stl_mesh(write("upper.stl", text)));
  // Two solids, the second empty: their triangles together.
  const TriangleMesh two = read_stl_mesh(write("two.stl", ascii_cube() + "solid\nendsolid\n"));
  EXPECT_EQ(two.vertices.size(), 8u);
  EXPECT_EQ(two.triangles.size(), 12u);
}

// Exactly equal positions weld, -0 and 0 included; positions a float step apart do not.
TEST_F(StlMeshReader, OnlyExactlyEqualPositionsWeld) {
  const std::string facets =
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex -0 0 -0\nvertex 1.0000001 0 0\n"
      "vertex 0 1e0 0\nendloop\nendfacet\nendsolid s\n";
  const TriangleMesh mesh = read_stl_mesh(write("weld.stl", facets));
  ASSERT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.triangles[1], Eigen::Vector3i(0, 3, 2));
  EXPECT_EQ(mesh.vertices[3], Eigen::Vector3f(1.0000001f, 0, 0));
}

TEST_F(StlMeshReader, BinaryRefusalsNameTheByteAndTheReason) {
  std::string truncated = binary_cube();
  truncated.resize(truncated.size() - 7);
  EXPECT_EQ(read_error(truncated),
            ": byte 80: the header claims 12 triangles, which take 84 + 50 * 12 = 684 bytes, but "
            "the file has 677");
  EXPECT_EQ(read_error(binary_cube("cube", 4000000000u)),
            ": byte 80: the header claims 4000000000 triangles, which take 84 + 50 * 4000000000 "
            "= 200000000084 bytes, but the file has 684");
  EXPECT_EQ(read_error(binary_cube() + "\n"),
            ": byte 80: the header claims 12 triangles, which take 84 + 50 * 12 = 684 bytes, but "
            "the file has 685");
  EXPECT_EQ(read_error(""), ": byte 0: empty file");
  EXPECT_EQ(read_error(std::string(83, 'x')),
            ": byte 0: 83 bytes: neither ASCII STL (it does not start with 'solid') nor binary "
            "(80 bytes of header and a 4-byte triangle count)");
  // The third triangle's second corner (byte 84 + 2 * 50 + 12 + 12 = 208) made NaN.
  std::string nan = binary_cube();
  const float not_a_number = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan[208 + 4], &not_a_number, 4);
  EXPECT_EQ(read_error(nan),
            ": byte 208: triangle 2 corner 1 (1, nan, 1) has a NaN or infinite coordinate");
  // A truncated binary file whose header starts with "solid" holds NUL bytes: not ASCII.
  std::string solid = binary_cube("solid");
  solid.resize(300);
  EXPECT_EQ(read_error(solid),
            ": byte 80: the header claims 12 triangles, which take 84 + 50 * 12 = 684 bytes, but "
            "the file has 300");
}

TEST_F(StlMeshReader, AsciiRefusalsNameTheLineAndTheReason) {
  const std::string facet_start = "solid s\nfacet normal 0 0 1\nouter loop\n";
  struct Case {
    std::string text;
    const char* reason;
  };
  const Case cases[] = {
      {"solid s\n", ":2: the file ends before endsolid"},
      {"solid s\nfacet normal 0 0 1\n", ":3: the file ends inside facet 0"},
      {facet_start + "vertex 0 0 0\nvertex 1 x 0\n", ":5: facet 0 vertex has 'x', not a number"},
      {facet_start + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1e39 0\nendloop\nendfacet\n",
       ":6: facet 0 vertex (0, inf, 0) has a NaN or infinite coordinate"},
      {facet_start + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 nan 0\nendloop\nendfacet\n",
       ":6: facet 0 vertex (0, nan, 0) has a NaN or infinite coordinate"},
      {facet_start + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\nendloop\n",
       ":7: facet 0 has 'vertex' where endloop was expected"},
      {facet_start + "vertex 0 0 0\nvertex 1 0 0\nendloop\n",
       ":6: facet 0 has 'endloop' where vertex was expected"},
      {"solid s\nfacet normal 0 zero 1\n", ":2: facet 0 normal has 'zero', not a number"},
      {"solid s\nfacets\n", ":2: 'facets' where facet or endsolid was expected"},
      {"solid s\nendsolid s\nsolid\nendsolid\ngarbage\n",
       ":5: 'garbage' after endsolid, where another solid or the end of the file was expected"},
  };
  for (const Case& c : cases) EXPECT_EQ(read_error(c.text), c.reason) << c.text;
}

}  // namespace
}  // namespace cosmos
