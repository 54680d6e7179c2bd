// Mesh loading through assimp: each supported format reads a known solid, the loaded part is
// centred and scaled to its size, and each defect of a file is one InputError line naming it.
#include "sim/mesh.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class MeshFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "cosmos-mesh-test-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }

  // The message of the InputError that loading `path` throws ("" when none is thrown).
  static std::string load_error(const fs::path& path, double size_mm = 100.0) {
    try {
      load_mesh(path, size_mm);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }

  fs::path dir_;
};

// A 2 x 3 x 4 box off the origin, as quads: the loader must triangulate, centre and scale it.
constexpr const char* kBoxOff =
    "OFF\n8 6 0\n"
    "10 20 30\n12 20 30\n12 23 30\n10 23 30\n10 20 34\n12 20 34\n12 23 34\n10 23 34\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

constexpr const char* kBoxObj =
    "# box\n"
    "v 10 20 30\nv 12 20 30\nv 12 23 30\nv 10 23 30\nv 10 20 34\nv 12 20 34\nv 12 23 34\nv 10 23 "
    "34\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

// The tetrahedron (0,0,0) (1,0,0) (0,2,0) (0,0,4): extents 1 x 2 x 4.
constexpr const char* kTetraPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float "
    "z\n"
    "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 2 0\n0 0 4\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

std::string stl_facet(const char* a, const char* b, const char* c) {
  return std::string("facet normal 0 0 0\nouter loop\nvertex ") + a + "\nvertex " + b +
         "\nvertex " + c + "\nendloop\nendfacet\n";
}

std::string tetra_stl() {
  return "solid tetra\n" + stl_facet("0 0 0", "0 2 0", "1 0 0") +
         stl_facet("0 0 0", "1 0 0", "0 0 4") + stl_facet("1 0 0", "0 2 0", "0 0 4") +
         stl_facet("0 0 0", "0 0 4", "0 2 0") + "endsolid tetra\n";
}

void expect_centred_at_size(const TriangleMesh& mesh, const Eigen::Vector3d& expected_sizes_mm) {
  const Eigen::AlignedBox3f box = bounding_box(mesh);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(box.sizes()[axis], expected_sizes_mm[axis], 1e-3 * expected_sizes_mm.maxCoeff())
        << "axis " << axis;
    EXPECT_NEAR(box.center()[axis], 0.0, 1e-4 * expected_sizes_mm.maxCoeff()) << "axis " << axis;
  }
}

TEST_F(MeshFiles, OffQuadBoxIsTriangulatedCentredAndScaled) {
  const TriangleMesh mesh = load_mesh(write("box.off", kBoxOff), 50.0);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  expect_centred_at_size(mesh, {25.0, 37.5, 50.0});
}

TEST_F(MeshFiles, ObjQuadBoxIsTriangulatedCentredAndScaled) {
  const TriangleMesh mesh = load_mesh(write("box.obj", kBoxObj), 120.0);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  expect_centred_at_size(mesh, {60.0, 90.0, 120.0});
}

TEST_F(MeshFiles, PlyTetrahedronIsCentredAndScaled) {
  const TriangleMesh mesh = load_mesh(write("tetra.ply", kTetraPly), 80.0);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.triangles.size(), 4u);
  expect_centred_at_size(mesh, {20.0, 40.0, 80.0});
}

TEST_F(MeshFiles, StlTetrahedronCornersAreWelded) {
  // STL stores three corners per facet; welding gives back the solid's 4 vertices.
  const TriangleMesh mesh = load_mesh(write("tetra.stl", tetra_stl()), 60.0);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.triangles.size(), 4u);
  expect_centred_at_size(mesh, {15.0, 30.0, 60.0});
}

TEST_F(MeshFiles, ReadKeepsFileUnitsAndUpperCaseExtensionsWork) {
  const TriangleMesh mesh = read_mesh_file(write("BOX.OFF", kBoxOff));
  const Eigen::AlignedBox3f box = bounding_box(mesh);
  EXPECT_NEAR(box.min().x(), 10.0f, 1e-6f);
  EXPECT_NEAR(box.max().z(), 34.0f, 1e-6f);
}

TEST_F(MeshFiles, TrianglesIndexExistingVertices) {
  const TriangleMesh mesh = read_mesh_file(write("box.obj", kBoxObj));
  for (const auto& triangle : mesh.triangles) {
    EXPECT_GE(triangle.minCoeff(), 0);
    EXPECT_LT(triangle.maxCoeff(), static_cast<int>(mesh.vertices.size()));
  }
}

void expect_one_line_naming(const std::string& message, const fs::path& path,
                            const std::string& reason) {
  ASSERT_FALSE(message.empty()) << "no InputError for " << path;
  EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_NE(message.find(reason), std::string::npos) << message;
}

TEST_F(MeshFiles, MissingFileIsNamed) {
  const fs::path path = dir_ / "absent.off";
  expect_one_line_naming(load_error(path), path, "mesh file not found");
}

TEST_F(MeshFiles, UnknownExtensionIsNamed) {
  const fs::path path = write("box.xyz", kBoxOff);
  expect_one_line_naming(load_error(path), path, "unknown mesh extension '.xyz'");
}

TEST_F(MeshFiles, EmptyMeshIsRefused) {
  const fs::path off = write("empty.off", "OFF\n0 0 0\n");
  const std::string off_message = load_error(off);
  expect_one_line_naming(off_message, off, "");
  std::cout << "[ message  ] " << off_message << "\n";
  // Vertices without a single face: no surface to scan.
  const fs::path obj = write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  const std::string obj_message = load_error(obj);
  expect_one_line_naming(obj_message, obj, "");
  std::cout << "[ message  ] " << obj_message << "\n";
}

TEST_F(MeshFiles, NanVertexIsRefused) {
  const fs::path path =
      write("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n");
  expect_one_line_naming(load_error(path), path,
                         "vertex (0, nan, 0) has a NaN or infinite coordinate");
}

TEST_F(MeshFiles, InfiniteVertexIsRefused) {
  const fs::path path = write("inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n");
  expect_one_line_naming(load_error(path), path, "NaN or infinite coordinate");
}

TEST_F(MeshFiles, ZeroSizeMeshIsRefused) {
  const fs::path path = write("point.off", "OFF\n3 1 0\n5 5 5\n5 5 5\n5 5 5\n3 0 1 2\n");
  expect_one_line_naming(load_error(path), path, "zero size");
}

TEST_F(MeshFiles, NonPositiveTargetSizeIsRefused) {
  const fs::path path = write("box.off", kBoxOff);
  expect_one_line_naming(load_error(path, 0.0), path, "size_mm must be finite and > 0");
  expect_one_line_naming(load_error(path, -5.0), path, "size_mm must be finite and > 0");
}

TEST_F(MeshFiles, GarbageIsAnAssimpFailureOnOneLine) {
  const fs::path path = write("garbage.ply", "this is not\na ply file\n");
  expect_one_line_naming(load_error(path), path, "assimp cannot read it");
}

}  // namespace
}  // namespace cosmos
