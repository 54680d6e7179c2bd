#pragma once
// Mesh files written into a fresh temporary folder per test, the one-line InputError contract
// every mesh reader keeps, and the square pyramid the OFF and PLY readers' tests both read
// (tests/sim/mesh_test.cpp and the readers' tests).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.hpp"
#include "sim/polygon_mesh.hpp"

namespace cosmos {

class MeshFileFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "cosmos-mesh-test-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& bytes) const {
    const std::filesystem::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  // The message of the InputError that `read` throws ("" when none is thrown).
  template <typename Read>
  static std::string error_of(Read&& read) {
    try {
      read();
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }

  // What follows the file's name in the InputError `read` throws for `path`, once checked to
  // be one line starting with the name: ":LINE: reason" or ": byte N: reason".
  template <typename Read>
  static std::string after_file_name(const std::filesystem::path& path, Read&& read) {
    const std::string message = error_of(std::forward<Read>(read));
    EXPECT_EQ(message.rfind(path.string() + ":", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message.substr(std::min(message.size(), path.string().size()));
  }

  std::filesystem::path dir_;
};

// One line, starting with the file's name, holding `reason`.
inline void expect_one_line_naming(const std::string& message, const std::filesystem::path& path,
                                   const std::string& reason) {
  ASSERT_FALSE(message.empty()) << "no InputError for " << path;
  EXPECT_EQ(message.rfind(path.string() + ":", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_NE(message.find(reason), std::string::npos) << message;
}

// The square pyramid (0,0,0) (2,0,0) (2,2,0) (0,2,0) apex (1,1,3): a quad base, then the four
// triangles up to the apex, as a file holds it.
inline void expect_square_pyramid(const PolygonMesh& mesh) {
  ASSERT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh.vertices[4], Eigen::Vector3f(1, 1, 3));
  EXPECT_EQ(mesh.vertices[2], Eigen::Vector3f(2, 2, 0));
  EXPECT_EQ(mesh.face_corners, (std::vector<int>{4, 3, 3, 3, 3}));
  ASSERT_EQ(mesh.corners.size(), 16u);
  EXPECT_EQ((std::vector<int>(mesh.corners.begin(), mesh.corners.begin() + 4)),
            (std::vector<int>{0, 3, 2, 1}));
  EXPECT_EQ(mesh.corners.back(), 4);
}

}  // namespace cosmos
