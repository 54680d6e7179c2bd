#include "sim/off_mesh_reader.hpp"

#include <climits>
#include <string>
#include <string_view>
#include <utility>

#include "sim/mesh_text.hpp"

namespace cosmos {
namespace {

constexpr bool kHashComments = true;

// The prefixes the OFF keyword may carry before "OFF" for per-vertex data this reader skips.
bool skippable_keyword_prefix(std::string_view prefix) {
  if (prefix.starts_with("ST")) prefix.remove_prefix(2);
  if (prefix.starts_with("C")) prefix.remove_prefix(1);
  if (prefix.starts_with("N")) prefix.remove_prefix(1);
  return prefix.empty();
}

long long count_in(const MeshText& text, std::string_view token, const char* what) {
  const auto count = parse_integer(token);
  if (!count || *count < 0)
    text.fail("the OFF counts line has " + std::string(what) + " count '" + std::string(token) +
              "', not a count >= 0");
  return *count;
}

std::string header_claims(long long count, const char* what, std::size_t bytes) {
  return "the header claims " + std::to_string(count) + " " + what + ", more than its " +
         std::to_string(bytes) + " bytes of data can hold";
}

// Every count weighed against the bytes left before anything is reserved for it: a vertex
// takes at least "0 0 0\n", a face at least "3 0 1 2\n".
void check_counts_fit(const MeshText& text, long long vertices, long long faces) {
  const std::size_t bytes = text.bytes_after_cursor();
  if (static_cast<double>(vertices) * 6 > static_cast<double>(bytes) || vertices > INT_MAX)
    text.fail(header_claims(vertices, "vertices", bytes));
  if (static_cast<double>(vertices) * 6 + static_cast<double>(faces) * 8 >
      static_cast<double>(bytes))
    text.fail(header_claims(faces, "faces", bytes));
}

// The keyword (optional in the format) and the counts line; returns {vertices, faces}. The
// edge count, when there is one, is not used.
std::pair<long long, long long> read_counts(MeshText& text) {
  if (!text.next_data_line(kHashComments)) text.fail("empty OFF file: no counts line");
  std::string_view vertices = text.token_on_line(kHashComments);
  if (vertices.ends_with("OFF")) {
    if (!skippable_keyword_prefix(vertices.substr(0, vertices.size() - 3)))
      text.fail("OFF keyword '" + std::string(vertices) +
                "' is none of [ST][C][N]OFF (4OFF and nOFF are not supported)");
    vertices = text.token_on_line(kHashComments);
    if (vertices.empty()) {
      if (!text.next_data_line(kHashComments)) text.fail("the OFF file ends before its counts");
      vertices = text.token_on_line(kHashComments);
    }
  }
  const long long vertex_count = count_in(text, vertices, "vertex");
  const long long face_count = count_in(text, text.token_on_line(kHashComments), "face");
  check_counts_fit(text, vertex_count, face_count);
  text.skip_line();
  return {vertex_count, face_count};
}

void read_vertex(MeshText& text, long long v, long long vertices, PolygonMesh& mesh) {
  if (!text.next_data_line(kHashComments))
    text.fail("the file ends before vertex " + std::to_string(v) + " (the header claims " +
              std::to_string(vertices) + ")");
  Eigen::Vector3f vertex;
  for (int axis = 0; axis < 3; ++axis) {
    const auto value = parse_number(text.token_on_line(kHashComments));
    if (!value) text.fail("vertex " + std::to_string(v) + " is not three numbers");
    vertex[axis] = static_cast<float>(*value);
  }
  if (const auto defect = vertex_defect(vertex))
    text.fail("vertex " + std::to_string(v) + " " + *defect);
  mesh.vertices.push_back(vertex);
  text.skip_line();
}

void read_face(MeshText& text, long long f, long long faces, PolygonMesh& mesh) {
  if (!text.next_data_line(kHashComments))
    text.fail("the file ends before face " + std::to_string(f) + " (the header claims " +
              std::to_string(faces) + ")");
  const std::string_view count_token = text.token_on_line(kHashComments);
  const auto corners = parse_integer(count_token);
  // Each corner is a token of the file, so a count beyond its bytes cannot be true.
  if (!corners || *corners < 3 || *corners > static_cast<long long>(text.bytes_after_cursor()))
    text.fail("face " + std::to_string(f) + " does not start with a vertex count of 3 or more ('" +
              std::string(count_token) + "')");
  const auto vertices = static_cast<long long>(mesh.vertices.size());
  for (long long k = 0; k < *corners; ++k) {
    const auto index = parse_integer(text.token_on_line(kHashComments));
    if (!index)
      text.fail("face " + std::to_string(f) + " has fewer than " + std::to_string(*corners) +
                " vertex indices");
    if (*index < 0 || *index >= vertices)
      text.fail("face " + std::to_string(f) + " indexes vertex " + std::to_string(*index) +
                ", the file has " + std::to_string(vertices) + " vertices");
    mesh.corners.push_back(static_cast<int>(*index));
  }
  mesh.face_corners.push_back(static_cast<int>(*corners));
  text.skip_line();
}

}  // namespace

PolygonMesh read_off_mesh(const std::filesystem::path& path) {
  MeshText text(path);
  const auto [vertices, faces] = read_counts(text);
  PolygonMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(vertices));
  mesh.face_corners.reserve(static_cast<std::size_t>(faces));
  mesh.corners.reserve(static_cast<std::size_t>(faces) * 3);
  for (long long v = 0; v < vertices; ++v) read_vertex(text, v, vertices, mesh);
  for (long long f = 0; f < faces; ++f) read_face(text, f, faces, mesh);
  return mesh;
}

}  // namespace cosmos
