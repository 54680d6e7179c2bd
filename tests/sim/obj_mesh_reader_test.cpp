// The OBJ reader: every corner form and relative indices read to the same polygons, what
// carries no surface is skipped, and each malformed file is refused on one line naming the file
// and its line.
#include "sim/obj_mesh_reader.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/sim/mesh_file_fixture.hpp"

namespace cosmos {
namespace {

class ObjMeshReader : public MeshFileFixture {
 protected:
  std::string read_error(const std::string& text) const {
    const auto path = write("bad.obj", text);
    return after_file_name(path, [&] { read_obj_mesh(path); });
  }
};

// The square pyramid of the OFF and PLY readers' tests: a quad base and 4 triangles.
constexpr const char* kPyramid =
    "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 1 1 3\n"
    "f 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";

TEST_F(ObjMeshReader, ReadsVerticesAndPolygonFacesAsTheFileHasThem) {
  expect_square_pyramid(read_obj_mesh(write("pyramid.obj", kPyramid)));
}

// Each corner form, relative indices (counted back from the last vertex read before the face),
// and the statements with no surface in them read to the same pyramid.
TEST_F(ObjMeshReader, CornerFormsRelativeIndicesAndOtherStatementsReadTheSame) {
  expect_square_pyramid(read_obj_mesh(write(
      "forms.obj",
      "# a pyramid\nmtllib pyramid.mtl\no pyramid\ng base\ns off\nusemtl stone\n"
      "v 0 0 0\nv 2 0 0 1.0\nv 2 2 0 0.5 0.5 0.5\nv 0 2 0\r\nvt 0 0\nvt 1 0\nvt 1 1\n"
      "vn 0 0 -1\nvn 0 1 0\nf -4/1/1 -1/2/1 -2/3/1 -3/1/1 # base\n"
      "v 1 1 3\nl 1 5\np 5\ng sides\nf 1/1 2/2 5/3\nf 2//2 3//2 5//2\rf -3 -2 -1\nf 4 1 -1\n")));
}

TEST_F(ObjMeshReader, CoordinatesAndLargePolygonsAreKept) {
  const PolygonMesh mesh = read_obj_mesh(
      write("hexagon.obj",
            "\xEF\xBB\xBFv 0 0 0\nv 2 0 0\nv 3 1.5 0\nv 2 3 0\nv 0 3 0\nv -1 1.5e0 0\n"
            "f 1 2 3 4 5 6\n"));
  ASSERT_EQ(mesh.vertices.size(), 6u);
  EXPECT_EQ(mesh.vertices[5], Eigen::Vector3f(-1, 1.5f, 0));
  EXPECT_EQ(mesh.face_corners, std::vector<int>{6});
  EXPECT_EQ(mesh.corners, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(triangulate(mesh).triangles.size(), 4u);
  // A byte order mark before a comment, or before a blank and the first statement.
  EXPECT_EQ(read_obj_mesh(write("bom.obj", "\xEF\xBB\xBF# pyramid\n" + std::string(kPyramid)))
                .vertices.size(),
            5u);
  expect_square_pyramid(
      read_obj_mesh(write("bom_blank.obj", "\xEF\xBB\xBF " + std::string(kPyramid))));
}

TEST_F(ObjMeshReader, EachRefusalNamesTheLineAndTheReason) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  struct Case {
    std::string text;
    const char* reason;
  };
  const Case cases[] = {
      {triangle + "f 0 1 2\n", ":4: face 1 indexes vertex 0 (OBJ counts from 1)"},
      {triangle + "f 1 2 3\nf 1 2 4\n",
       ":5: face 2 indexes vertex 4, and 3 vertices come before it"},
      {"v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n",
       ":2: face 1 indexes vertex 2, and 1 vertices come before it"},
      {triangle + "f -1 -2 -4\n",
       ":4: face 1 indexes vertex -4 (counted back from the last), and 3 vertices come before "
       "it"},
      {triangle + "f 1 2 99999999999999999999\n",
       ":4: face 1 has corner '99999999999999999999', none of i, i/t, i//n, i/t/n with integers"},
      {triangle + "f 1 2/x 3\n",
       ":4: face 1 has corner '2/x', none of i, i/t, i//n, i/t/n with integers"},
      {triangle + "f 1 2// 3\n",
       ":4: face 1 has corner '2//', none of i, i/t, i//n, i/t/n with integers"},
      {triangle + "f 1 2\n", ":4: face 1 has 2 corners, fewer than 3"},
      {triangle + "f\n", ":4: face 1 has 0 corners, fewer than 3"},
      {"v 0 0 0\nv 1 zero 0\n", ":2: vertex 2 has 'zero', not a number"},
      {"v 0 0\n", ":1: vertex 1 has 2 numbers, not x y z, x y z w or x y z r g b"},
      {"v 0 0 0 1 1\n", ":1: vertex 1 has 5 numbers, not x y z, x y z w or x y z r g b"},
      {"v 0 0 0 1 1 1 1\n", ":1: vertex 1 has more than 6 numbers"},
      {"v 0 0 0\n\nv 0 nan 0\n", ":3: vertex 2 (0, nan, 0) has a NaN or infinite coordinate"},
      {"v 0 1e39 0\n", ":1: vertex 1 (0, inf, 0) has a NaN or infinite coordinate"},
      {triangle + "f 1 2 \\\n 3\n",
       ":4: line continuations ('\\' at a line's end) are not supported"},
      {"cstype bspline\n",
       ":1: free-form geometry ('cstype') is not supported: only polygon "
       "faces are read"},
      {"vertex 0 0 0\n", ":1: 'vertex' is not an OBJ statement this reader knows"},
      {"solid s\n", ":1: 'solid' is not an OBJ statement this reader knows"},
      // UTF-16: bytes no terminal should get, and a token longer than a message shows.
      {std::string("\xfe\xff\0v\0 \x01", 7) + std::string(60, 'x') + "\n",
       ":1: '\\xfe\\xff\\x00v\\x00' is not an OBJ statement this reader knows"},
      {"v 0 0 0 " + std::string(60, '9') + "x\n",
       ":1: vertex 1 has '9999999999999999999999999999999999999999...', not a number"},
  };
  for (const Case& c : cases) EXPECT_EQ(read_error(c.text), c.reason) << c.text;
}

// A file without a face reads to no polygons; read_mesh_file refuses it as a mesh without
// triangles (tests/sim/mesh_test.cpp).
TEST_F(ObjMeshReader, EmptyFileAndVerticesWithoutFacesHaveNoPolygons) {
  EXPECT_TRUE(read_obj_mesh(write("empty.obj", "")).face_corners.empty());
  const PolygonMesh points = read_obj_mesh(write("points.obj", "v 0 0 0\nv 1 0 0\np 1 2\n"));
  EXPECT_EQ(points.vertices.size(), 2u);
  EXPECT_TRUE(points.face_corners.empty());
}

}  // namespace
}  // namespace cosmos
