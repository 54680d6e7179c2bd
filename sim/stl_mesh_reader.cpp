#include "sim/stl_mesh_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>

#include "sim/mesh_text.hpp"

namespace cosmos {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kCountBytes = 4;
constexpr std::size_t kTriangleBytes = 50;  // normal, three corners (12 floats), attribute word

// Corners welded by exact position: the three coordinates' bits, -0 made +0 first so the two
// zeros (equal as numbers) are one vertex, as they are in read_mesh_file's compaction.
class CornerWelder {
 public:
  explicit CornerWelder(TriangleMesh& mesh) : mesh_(mesh) {}

  void reserve(std::size_t corners) { index_of_.reserve(corners); }

  int index(const Eigen::Vector3f& position) {
    Key key;
    for (int axis = 0; axis < 3; ++axis) {
      const float coordinate = position[axis] + 0.0f;
      std::memcpy(&key[static_cast<std::size_t>(axis)], &coordinate, sizeof coordinate);
    }
    const auto [at, added] = index_of_.try_emplace(key, static_cast<int>(mesh_.vertices.size()));
    if (added) mesh_.vertices.push_back(position);
    return at->second;
  }

 private:
  using Key = std::array<std::uint32_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      std::uint64_t hash = 0x9e3779b97f4a7c15ull;
      for (std::uint32_t bits : key) hash = (hash ^ bits) * 0x100000001b3ull;
      return static_cast<std::size_t>(hash ^ (hash >> 29));
    }
  };

  TriangleMesh& mesh_;
  std::unordered_map<Key, int, KeyHash> index_of_;
};

bool is_keyword(std::string_view token, std::string_view keyword) {
  return token.size() == keyword.size() &&
         std::equal(token.begin(), token.end(), keyword.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

// What common readers take for an ASCII file: "solid" first, and text throughout (a binary
// body almost always holds a NUL byte: a zero coordinate, a count below 2^24).
bool looks_ascii(const MeshText& text) {
  const std::string& bytes = text.bytes();
  return is_keyword(std::string_view(bytes).substr(0, 5), "solid") &&
         std::memchr(bytes.data(), '\0', bytes.size()) == nullptr;
}

// ---- binary ----

// The count and the size agree to the byte: a short file is cut off, and a longer one holds
// bytes the count does not describe, refused rather than guessed at.
bool binary_size_consistent(const MeshText& text) {
  const std::string& bytes = text.bytes();
  if (bytes.size() < kHeaderBytes + kCountBytes) return false;
  const std::uint64_t triangles = unsigned_at(bytes, kHeaderBytes, kCountBytes);
  return kHeaderBytes + kCountBytes + kTriangleBytes * triangles == bytes.size();
}

[[noreturn]] void refuse_binary_size(const MeshText& text) {
  const std::string& bytes = text.bytes();
  const std::string size = std::to_string(bytes.size());
  if (bytes.empty()) text.fail_in_file("byte 0: empty file");
  if (bytes.size() < kHeaderBytes + kCountBytes)
    text.fail_in_file("byte 0: " + size +
                      " bytes: neither ASCII STL (it does not start with 'solid') nor binary "
                      "(80 bytes of header and a 4-byte triangle count)");
  const std::uint64_t triangles = unsigned_at(bytes, kHeaderBytes, kCountBytes);
  text.fail_in_file("byte 80: the header claims " + std::to_string(triangles) +
                    " triangles, which take 84 + 50 * " + std::to_string(triangles) + " = " +
                    std::to_string(kHeaderBytes + kCountBytes + kTriangleBytes * triangles) +
                    " bytes, but the file has " + size);
}

TriangleMesh read_binary(const MeshText& text) {
  const std::string& bytes = text.bytes();
  const auto triangles =
      static_cast<std::size_t>(unsigned_at(bytes, kHeaderBytes, kCountBytes));  // fits the file
  TriangleMesh mesh;
  mesh.triangles.reserve(triangles);
  CornerWelder welder(mesh);
  welder.reserve(triangles);  // a closed surface has about half as many vertices
  for (std::size_t t = 0; t < triangles; ++t) {
    Eigen::Vector3i triangle;
    for (int corner = 0; corner < 3; ++corner) {
      // The facet normal (12 bytes) comes first.
      const std::size_t at = kHeaderBytes + kCountBytes + kTriangleBytes * t + 12 + 12 * corner;
      Eigen::Vector3f position;
      for (int axis = 0; axis < 3; ++axis)
        position[axis] =
            float_of_bits(static_cast<std::uint32_t>(unsigned_at(bytes, at + 4 * axis, 4)));
      if (const auto defect = vertex_defect(position))
        text.fail_in_file("byte " + std::to_string(at) + ": triangle " + std::to_string(t) +
                          " corner " + std::to_string(corner) + " " + *defect);
      triangle[corner] = welder.index(position);
    }
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

// ---- ASCII ----

class AsciiStlReader {
 public:
  explicit AsciiStlReader(MeshText& text) : text_(text), welder_(mesh_) {}

  TriangleMesh read() {
    text_.token();      // "solid", checked by looks_ascii
    text_.skip_line();  // the solid's name, which may hold blanks
    for (;;) {
      const std::string_view token = text_.token();
      if (is_keyword(token, "facet")) {
        read_facet();
      } else if (is_keyword(token, "endsolid")) {
        text_.skip_line();
        const std::string_view next = text_.token();
        if (next.empty()) return std::move(mesh_);
        if (!is_keyword(next, "solid"))
          text_.fail(quoted(next) +
                     " after endsolid, where another solid or the "
                     "end of the file was expected");
        text_.skip_line();
      } else if (token.empty()) {
        text_.fail("the file ends before endsolid");
      } else {
        text_.fail(quoted(token) + " where facet or endsolid was expected");
      }
    }
  }

 private:
  void expect(std::string_view keyword) {
    const std::string_view token = text_.token();
    if (is_keyword(token, keyword)) return;
    if (token.empty()) text_.fail("the file ends inside facet " + std::to_string(facet_));
    text_.fail("facet " + std::to_string(facet_) + " has " + quoted(token) + " where " +
               std::string(keyword) + " was expected");
  }

  double number(const char* what) {
    const std::string_view token = text_.token();
    const auto value = parse_number(token);
    if (!value)
      text_.fail("facet " + std::to_string(facet_) + " " + what + " has " + quoted(token) +
                 ", not a number");
    return *value;
  }

  void read_facet() {
    expect("normal");
    for (int axis = 0; axis < 3; ++axis) number("normal");
    expect("outer");
    expect("loop");
    Eigen::Vector3i triangle;
    for (int corner = 0; corner < 3; ++corner) {
      expect("vertex");
      Eigen::Vector3f position;
      for (int axis = 0; axis < 3; ++axis) position[axis] = static_cast<float>(number("vertex"));
      if (const auto defect = vertex_defect(position))
        text_.fail("facet " + std::to_string(facet_) + " vertex " + *defect);
      triangle[corner] = welder_.index(position);
    }
    expect("endloop");
    expect("endfacet");
    mesh_.triangles.push_back(triangle);
    ++facet_;
  }

  MeshText& text_;
  TriangleMesh mesh_;
  CornerWelder welder_;
  long long facet_ = 0;
};

}  // namespace

TriangleMesh read_stl_mesh(const std::filesystem::path& path) {
  MeshText text(path);
  if (binary_size_consistent(text)) return read_binary(text);
  if (looks_ascii(text)) return AsciiStlReader(text).read();
  refuse_binary_size(text);
}

}  // namespace cosmos
