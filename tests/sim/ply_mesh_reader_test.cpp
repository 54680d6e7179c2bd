// The PLY reader: ASCII and both binary byte orders read to the same polygons whatever the
// property types, what the mesh does not use is skipped, and each malformed file is refused on
// one line naming the file and its line (header, ASCII) or byte (binary body).
#include "sim/ply_mesh_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "tests/sim/mesh_file_fixture.hpp"

namespace cosmos {
namespace {

class PlyMeshReader : public MeshFileFixture {
 protected:
  std::string read_error(const std::string& text) const {
    const auto path = write("bad.ply", text);
    return error_of([&] { read_ply_mesh(path); });
  }
};

// A square pyramid: a quad base, 4 triangles, and an edge (2 corners) the reader drops.
const float kVertices[5][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 3}};
const std::vector<std::vector<int>> kFaces = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4},
                                              {2, 3, 4},    {3, 0, 4}, {0, 4}};

// The header: each vertex has a colour byte before its coordinates and a normal after them,
// each face a flag after its list, and an element the mesh does not use comes between.
std::string header(const std::string& format, const std::string& coordinate,
                   const std::string& count, const std::string& index) {
  return "ply\nformat " + format + " 1.0\ncomment a pyramid\nelement vertex 5\n" +
         "property uchar red\nproperty " + coordinate + " x\nproperty " + coordinate +
         " y\nproperty " + coordinate + " z\nproperty float nx\n" +
         "element material 1\nproperty list uchar float shininess\n" +
         "element face 6\nproperty list " + count + " " + index +
         " vertex_indices\nproperty uchar flag\nend_header\n";
}

std::string ascii_pyramid() {
  std::ostringstream text;
  text << header("ascii", "float", "uchar", "int");
  for (const auto& v : kVertices) text << "7 " << v[0] << " " << v[1] << " " << v[2] << " 0.5\n";
  text << "2 0.25 0.75\n";
  for (const auto& face : kFaces) {
    text << face.size();
    for (int index : face) text << " " << index;
    text << " 1\n";
  }
  return text.str();
}

// A value's bytes in the given byte order.
template <typename Value>
void append(std::string& out, Value value, bool big_endian) {
  char bytes[sizeof(Value)];
  std::memcpy(bytes, &value, sizeof(Value));
  if (big_endian) std::reverse(bytes, bytes + sizeof(Value));
  out.append(bytes, sizeof(Value));
}

template <typename Coordinate, typename Count, typename Index>
std::string binary_pyramid(bool big_endian, const std::string& coordinate, const std::string& count,
                           const std::string& index) {
  std::string out =
      header(big_endian ? "binary_big_endian" : "binary_little_endian", coordinate, count, index);
  for (const auto& v : kVertices) {
    append<std::uint8_t>(out, 7, big_endian);
    for (float c : v) append(out, static_cast<Coordinate>(c), big_endian);
    append(out, 0.5f, big_endian);
  }
  append<std::uint8_t>(out, 2, big_endian);
  append(out, 0.25f, big_endian);
  append(out, 0.75f, big_endian);
  for (const auto& face : kFaces) {
    append(out, static_cast<Count>(face.size()), big_endian);
    for (int i : face) append(out, static_cast<Index>(i), big_endian);
    append<std::uint8_t>(out, 1, big_endian);
  }
  return out;
}

TEST_F(PlyMeshReader, AsciiReadsTheMeshAndSkipsTheRest) {
  expect_square_pyramid(read_ply_mesh(write("ascii.ply", ascii_pyramid())));
}

TEST_F(PlyMeshReader, BinaryReadsInBothByteOrdersWithAnyTypes) {
  expect_square_pyramid(
      read_ply_mesh(write("le.ply", binary_pyramid<float, std::uint8_t, std::int32_t>(
                                        false, "float", "uchar", "int"))));
  expect_square_pyramid(read_ply_mesh(write(
      "be.ply", binary_pyramid<float, std::uint8_t, std::int32_t>(true, "float", "uchar", "int"))));
  expect_square_pyramid(
      read_ply_mesh(write("be_wide.ply", binary_pyramid<double, std::uint32_t, std::uint16_t>(
                                             true, "double", "uint", "ushort"))));
  expect_square_pyramid(
      read_ply_mesh(write("le_short.ply", binary_pyramid<double, std::int16_t, std::uint32_t>(
                                              false, "float64", "int16", "uint32"))));
}

TEST_F(PlyMeshReader, CarriageReturnLineEndsReadTheSame) {
  std::string crlf = ascii_pyramid();
  for (std::size_t at = crlf.find('\n'); at != std::string::npos; at = crlf.find('\n', at + 2))
    crlf.replace(at, 1, "\r\n");
  expect_square_pyramid(read_ply_mesh(write("crlf.ply", crlf)));
  std::string binary =
      binary_pyramid<float, std::uint8_t, std::int32_t>(false, "float", "uchar", "int");
  binary.replace(binary.find("end_header\n"), 11, "end_header\r\n");
  expect_square_pyramid(read_ply_mesh(write("crlf_binary.ply", binary)));
}

TEST_F(PlyMeshReader, HeaderRefusalsNameTheLine) {
  const std::string good = ascii_pyramid();
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  struct Case {
    std::string text;
    const char* reason;
  };
  const Case cases[] = {
      {with("format ascii", "format binary_middle_endian"),
       ":2: PLY format 'binary_middle_endian' is none of"},
      {with("property uchar red", "property uint24 red"),
       ":5: PLY property type 'uint24' is unknown"},
      {with("list uchar int", "list float int"), ":13: PLY list count type is not an integer"},
      {with("list uchar int", "list uchar float"),
       ":12: PLY vertex_indices list of a non-integer type"},
      {with("element material 1", "element vertex 1"), ":10: a second PLY element vertex"},
      {with("element face 6", "element face six"), ":12: PLY element face has count 'six'"},
      {with("comment a pyramid", "commment a pyramid"),
       ":3: 'commment' is not a PLY header keyword"},
      {with("end_header\n", "end_header extra\n"), ":15: PLY end_header line has more on it"},
      {with("end_header\n", "end_headers\n"), ":15: 'end_headers' is not a PLY header keyword"},
      {"ply\nformat ascii 1.0\nproperty float x\nend_header\n", ":3: PLY property before any"},
      {"ply\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
       ":6: PLY header without a format line"},
      {"ply\nformat ascii 1.0\n", ":3: PLY header has no end_header line"},
  };
  for (const Case& c : cases) {
    const auto path = write("bad.ply", c.text);
    expect_one_line_naming(error_of([&] { read_ply_mesh(path); }), path, c.reason);
  }
}

TEST_F(PlyMeshReader, AsciiBodyRefusalsNameTheLine) {
  std::string text = ascii_pyramid();
  text.replace(text.find("1 1 3"), 5, "1 1 e");  // the fifth vertex, line 20
  EXPECT_NE(read_error(text).find(":20: 'e' is not a number"), std::string::npos);
  text = ascii_pyramid();
  text.replace(text.find("3 2 3 4"), 7, "3 2 5 4");  // face 3, line 25
  EXPECT_NE(read_error(text).find(":25: face 3 indexes vertex 5, the file has 5 vertices"),
            std::string::npos);
  text = ascii_pyramid();
  text.replace(text.find("3 3 0 4"), 7, "3 3 0.5 4");
  EXPECT_NE(read_error(text).find(":26: face 4 indexes vertex 0.5"), std::string::npos);
  text = ascii_pyramid();
  text.erase(text.find("2 0 4 1"));
  EXPECT_NE(read_error(text).find("the data ends inside face 5 (the header claims 6)"),
            std::string::npos);
}

TEST_F(PlyMeshReader, BinaryBodyRefusalsNameTheByte) {
  const std::string good =
      binary_pyramid<float, std::uint8_t, std::int32_t>(false, "float", "uchar", "int");
  const std::size_t body = good.find("end_header\n") + 11;
  // Vertex: 1 + 12 + 4 bytes; the material: 1 + 8; the first face's count is then at +94.
  const std::size_t first_face = body + 5 * 17 + 9;
  std::string huge_list = good;
  huge_list[first_face] = static_cast<char>(200);
  EXPECT_NE(read_error(huge_list).find("face 0 has a list of 200 values"), std::string::npos);
  std::string bad_index = good;
  const std::int32_t index = 1000;
  std::memcpy(&bad_index[first_face + 1 + 4], &index, 4);
  EXPECT_NE(read_error(bad_index).find(": byte " + std::to_string(first_face + 9) +
                                       ": face 0 indexes vertex 1000, the file has 5 vertices"),
            std::string::npos);
  std::string nan_vertex = good;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan_vertex[body + 17 + 1 + 4], &nan, 4);
  EXPECT_NE(read_error(nan_vertex).find("vertex 1 (2, nan, 0) has a NaN or infinite coordinate"),
            std::string::npos);
}

// A list's length and the header's counts are weighed against the bytes there are before
// anything is allocated for them (assimp reserved 26 GB for a fuzzed file's claim).
TEST_F(PlyMeshReader, ClaimsBeyondTheFilesBytesAreRefusedBeforeAnyAllocation) {
  const std::string good =
      binary_pyramid<float, std::uint8_t, std::int32_t>(true, "float", "uint", "int");
  std::string huge_list = good;
  const std::size_t first_face = good.find("end_header\n") + 11 + 5 * 17 + 9;
  const std::uint32_t length = 0xFFFFFFF0u;
  std::memcpy(&huge_list[first_face], &length, 4);  // big endian 0xF0FFFFFF
  EXPECT_NE(read_error(huge_list).find("face 0 has a list of 4043309055 values"),
            std::string::npos);
  std::string huge_count = good;
  huge_count.replace(huge_count.find("element face 6"), 14, "element face 3000000000");
  EXPECT_NE(read_error(huge_count).find(":12: the header claims 3000000000 face elements"),
            std::string::npos);
}

}  // namespace
}  // namespace cosmos
