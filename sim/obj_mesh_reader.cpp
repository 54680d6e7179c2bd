#include "sim/obj_mesh_reader.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <string>
#include <string_view>

#include "sim/mesh_text.hpp"

namespace cosmos {
namespace {

constexpr bool kHashComments = true;

// Statements with no polygon surface in them.
bool skipped_statement(std::string_view keyword) {
  static constexpr std::array<std::string_view, 21> kSkipped = {
      "vt",     "vn",     "vp",     "o",          "g",         "s",        "mg",
      "usemtl", "mtllib", "l",      "p",          "bevel",     "c_interp", "d_interp",
      "lod",    "maplib", "usemap", "shadow_obj", "trace_obj", "ctech",    "stech"};
  return std::find(kSkipped.begin(), kSkipped.end(), keyword) != kSkipped.end();
}

bool free_form_statement(std::string_view keyword) {
  return keyword == "cstype" || keyword == "curv" || keyword == "curv2" || keyword == "surf";
}

class ObjReader {
 public:
  explicit ObjReader(MeshText& text) : text_(text) {}

  PolygonMesh read() {
    while (text_.next_data_line(kHashComments)) {
      std::string_view keyword = text_.token_on_line(kHashComments);
      // Some editors begin a UTF-8 file with a byte order mark, before a blank or a comment too.
      if (text_.offset() == keyword.size() && keyword.starts_with("\xEF\xBB\xBF")) {
        keyword.remove_prefix(3);
        if (keyword.empty()) keyword = text_.token_on_line(kHashComments);
      }
      if (keyword == "v") {
        read_vertex();
      } else if (keyword == "f") {
        read_face();
      } else if (free_form_statement(keyword)) {
        text_.fail("free-form geometry (" + quoted(keyword) +
                   ") is not supported: only polygon faces are read");
      } else if (skipped_statement(keyword) || keyword.empty()) {  // empty: a lone mark
        skip_statement();
      } else {
        text_.fail(quoted(keyword) + " is not an OBJ statement this reader knows");
      }
      text_.skip_line();
    }
    return std::move(mesh_);
  }

 private:
  // The next token of the line, refusing a line continuation, which joins the next line.
  std::string_view token() {
    const std::string_view token = text_.token_on_line(kHashComments);
    if (token == "\\" && text_.token_on_line(kHashComments).empty())
      text_.fail("line continuations ('\\' at a line's end) are not supported");
    return token;
  }

  void skip_statement() {
    while (!token().empty()) {
    }
  }

  void read_vertex() {
    const std::size_t number = mesh_.vertices.size() + 1;
    if (number > INT_MAX) text_.fail("more than " + std::to_string(INT_MAX) + " vertices");
    std::array<double, 6> values{};
    std::size_t count = 0;
    for (std::string_view value = token(); !value.empty(); value = token()) {
      const auto parsed = parse_number(value);
      if (!parsed)
        text_.fail("vertex " + std::to_string(number) + " has " + quoted(value) + ", not a number");
      if (count == values.size())
        text_.fail("vertex " + std::to_string(number) + " has more than 6 numbers");
      values[count++] = *parsed;
    }
    if (count != 3 && count != 4 && count != 6)
      text_.fail("vertex " + std::to_string(number) + " has " + std::to_string(count) +
                 " numbers, not x y z, x y z w or x y z r g b");
    const Eigen::Vector3f position(static_cast<float>(values[0]), static_cast<float>(values[1]),
                                   static_cast<float>(values[2]));
    if (const auto defect = vertex_defect(position))
      text_.fail("vertex " + std::to_string(number) + " " + *defect);
    mesh_.vertices.push_back(position);
  }

  void read_face() {
    ++faces_;
    const std::size_t first_corner = mesh_.corners.size();
    for (std::string_view corner = token(); !corner.empty(); corner = token())
      mesh_.corners.push_back(vertex_of(corner));
    const std::size_t corners = mesh_.corners.size() - first_corner;
    if (corners < 3)
      text_.fail("face " + std::to_string(faces_) + " has " + std::to_string(corners) +
                 " corners, fewer than 3");
    mesh_.face_corners.push_back(static_cast<int>(corners));
  }

  // A corner "i", "i/t", "i//n" or "i/t/n" as the 0-based vertex it indexes.
  int vertex_of(std::string_view corner) {
    const std::size_t slash = corner.find('/');
    const std::string_view index = corner.substr(0, slash);
    bool well_formed = parse_integer(index).has_value();
    if (slash != std::string_view::npos) {
      const std::string_view rest = corner.substr(slash + 1);
      const std::size_t second = rest.find('/');
      const std::string_view texture = rest.substr(0, second);
      const std::string_view normal =
          second == std::string_view::npos ? std::string_view{} : rest.substr(second + 1);
      well_formed = well_formed && (second == std::string_view::npos
                                        ? parse_integer(texture).has_value()
                                        : (texture.empty() || parse_integer(texture).has_value()) &&
                                              parse_integer(normal).has_value());
    }
    if (!well_formed)
      text_.fail("face " + std::to_string(faces_) + " has corner " + quoted(corner) +
                 ", none of i, i/t, i//n, i/t/n with integers");
    const long long value = *parse_integer(index);
    const auto vertices = static_cast<long long>(mesh_.vertices.size());
    if (value == 0)
      text_.fail("face " + std::to_string(faces_) + " indexes vertex 0 (OBJ counts from 1)");
    if (value > vertices || value < -vertices)
      text_.fail("face " + std::to_string(faces_) + " indexes vertex " + std::to_string(value) +
                 (value < 0 ? " (counted back from the last), " : ", ") + "and " +
                 std::to_string(vertices) + " vertices come before it");
    return static_cast<int>(value > 0 ? value - 1 : vertices + value);
  }

  MeshText& text_;
  PolygonMesh mesh_;
  long long faces_ = 0;
};

}  // namespace

PolygonMesh read_obj_mesh(const std::filesystem::path& path) {
  MeshText text(path);
  return ObjReader(text).read();
}

}  // namespace cosmos
