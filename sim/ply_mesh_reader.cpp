#include "sim/ply_mesh_reader.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "sim/mesh_text.hpp"

namespace cosmos {
namespace {

struct PlyType {
  int bytes = 0;  // 0: not a PLY type
  bool is_signed = false;
  bool is_integer = false;
};

PlyType ply_type(std::string_view name) {
  if (name == "char" || name == "int8") return {1, true, true};
  if (name == "uchar" || name == "uint8") return {1, false, true};
  if (name == "short" || name == "int16") return {2, true, true};
  if (name == "ushort" || name == "uint16") return {2, false, true};
  if (name == "int" || name == "int32") return {4, true, true};
  if (name == "uint" || name == "uint32") return {4, false, true};
  if (name == "float" || name == "float32") return {4, true, false};
  if (name == "double" || name == "float64") return {8, true, false};
  return {};
}

struct PlyProperty {
  std::string name;
  PlyType type;        // the scalar's, or the list items'
  PlyType count_type;  // bytes > 0 for a list
  bool is_list() const { return count_type.bytes > 0; }
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::size_t line = 0;  // of its header line
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;
};

bool is_index_list(const PlyElement& element, const PlyProperty& property) {
  return element.name == "face" && property.is_list() &&
         (property.name == "vertex_indices" || property.name == "vertex_index");
}

PlyFormat read_format(MeshText& text) {
  const std::string_view name = text.token_on_line(false);
  if (name == "ascii") return PlyFormat::kAscii;
  if (name == "binary_little_endian") return PlyFormat::kBinaryLittleEndian;
  if (name == "binary_big_endian") return PlyFormat::kBinaryBigEndian;
  text.fail("PLY format '" + std::string(name) +
            "' is none of ascii, binary_little_endian, binary_big_endian");
}

PlyType read_type(MeshText& text, std::string_view name) {
  const PlyType type = ply_type(name);
  if (type.bytes == 0) text.fail("PLY property type '" + std::string(name) + "' is unknown");
  return type;
}

PlyProperty read_property(MeshText& text) {
  PlyProperty property;
  const std::string_view type = text.token_on_line(false);
  if (type == "list") {
    property.count_type = read_type(text, text.token_on_line(false));
    if (!property.count_type.is_integer) text.fail("PLY list count type is not an integer type");
    property.type = read_type(text, text.token_on_line(false));
  } else {
    property.type = read_type(text, type);
  }
  property.name = std::string(text.token_on_line(false));
  if (property.name.empty()) text.fail("PLY property without a name");
  return property;
}

PlyElement read_element(MeshText& text, const std::vector<PlyElement>& elements) {
  PlyElement element;
  element.line = text.line();
  element.name = std::string(text.token_on_line(false));
  const std::string_view count = text.token_on_line(false);
  const auto value = parse_integer(count);
  if (!value || *value < 0)
    text.fail("PLY element " + element.name + " has count '" + std::string(count) + "'");
  element.count = *value;
  if (std::any_of(elements.begin(), elements.end(),
                  [&](const PlyElement& e) { return e.name == element.name; }))
    text.fail("a second PLY element " + element.name);
  return element;
}

// What the mesh needs from its elements, declared as it reads them.
void check_elements(const MeshText& text, const std::vector<PlyElement>& elements) {
  for (const PlyElement& element : elements) {
    const auto has_scalar = [&](const char* name) {
      return std::any_of(element.properties.begin(), element.properties.end(),
                         [&](const PlyProperty& p) { return p.name == name && !p.is_list(); });
    };
    if (element.name == "vertex" && !(has_scalar("x") && has_scalar("y") && has_scalar("z")))
      text.fail_at(element.line, "PLY vertex element without properties x, y, z");
    if (element.name != "face") continue;
    const auto list = std::find_if(element.properties.begin(), element.properties.end(),
                                   [&](const PlyProperty& p) { return is_index_list(element, p); });
    if (list == element.properties.end())
      text.fail_at(element.line, "PLY face element without a vertex_indices list");
    if (!list->type.is_integer)
      text.fail_at(element.line, "PLY vertex_indices list of a non-integer type");
  }
}

// The header, up to the line "end_header" and the line break after it.
PlyHeader read_header(MeshText& text) {
  if (text.token_on_line(false) != "ply" || !text.token_on_line(false).empty())
    text.fail("not a PLY file (its first line is not 'ply')");
  PlyHeader header;
  bool has_format = false;
  for (;;) {
    text.skip_line();
    if (!text.next_data_line(false)) text.fail("PLY header has no end_header line");
    const std::string_view keyword = text.token_on_line(false);
    if (keyword == "end_header") break;
    if (keyword == "format") {
      header.format = read_format(text);
      has_format = true;
    } else if (keyword == "element") {
      header.elements.push_back(read_element(text, header.elements));
    } else if (keyword == "property") {
      if (header.elements.empty()) text.fail("PLY property before any element");
      header.elements.back().properties.push_back(read_property(text));
    } else if (keyword != "comment" && keyword != "obj_info") {
      text.fail(std::string("'").append(keyword).append("' is not a PLY header keyword"));
    }
  }
  if (!has_format) text.fail("PLY header without a format line");
  check_elements(text, header.elements);
  if (!text.token_on_line(false).empty()) text.fail("PLY end_header line has more on it");
  // A binary body starts right after the header's last line break, which is "\n" or "\r\n".
  const std::string& bytes = text.bytes();
  std::size_t body = text.offset();
  if (body < bytes.size() && bytes[body] == '\r') ++body;
  if (body < bytes.size() && bytes[body] == '\n') ++body;
  header.body_offset = body;
  return header;
}

// Reads the body's values one at a time, as text tokens or binary scalars, and refuses with
// the line (ASCII) or the byte offset (binary) of the value at hand.
class PlyBodyReader {
 public:
  PlyBodyReader(MeshText& text, const PlyHeader& header)
      : text_(text), format_(header.format), at_(header.body_offset) {}

  // The next value, or nothing at the end of the data.
  std::optional<double> value(const PlyType& type) {
    if (format_ == PlyFormat::kAscii) {
      const std::string_view token = text_.token();
      if (token.empty()) return std::nullopt;
      const auto number = parse_number(token);
      if (!number) fail(std::string("'").append(token).append("' is not a number"));
      return number;
    }
    return binary_value(type);
  }

  [[noreturn]] void fail(const std::string& reason) const {
    if (format_ == PlyFormat::kAscii) text_.fail(reason);
    text_.fail_in_file("byte " + std::to_string(at_) + ": " + reason);
  }

 private:
  std::optional<double> binary_value(const PlyType& type) {
    const std::string& bytes = text_.bytes();
    const auto size = static_cast<std::size_t>(type.bytes);
    if (size > bytes.size() - at_) return std::nullopt;
    const std::uint64_t bits =
        unsigned_at(bytes, at_, size, format_ == PlyFormat::kBinaryBigEndian);
    at_ += size;
    if (!type.is_integer) {
      if (size == 4) return float_of_bits(static_cast<std::uint32_t>(bits));
      double value;
      std::memcpy(&value, &bits, 8);
      return value;
    }
    if (type.is_signed && (bits >> (8 * size - 1)) != 0)
      return static_cast<double>(
          static_cast<std::int64_t>(bits | (~std::uint64_t{0} << (8 * size))));
    return static_cast<double>(bits);
  }

  MeshText& text_;
  PlyFormat format_;
  std::size_t at_;
};

std::string header_claims(const PlyElement& element, std::size_t bytes) {
  return "the header claims " + std::to_string(element.count) + " " + element.name +
         " elements, more than its " + std::to_string(bytes) + " bytes of data can hold";
}

// The fewest bytes each element can take, its scalars and list counts (empty lists), or in
// text one digit and one separator per value, weighed against the body before anything is
// allocated: a 200-byte header may claim 2e9 vertices.
void check_counts_fit(const MeshText& text, const PlyHeader& header) {
  const std::size_t body_bytes = text.bytes().size() - header.body_offset;
  double least_bytes = 0;
  for (const PlyElement& element : header.elements) {
    int element_bytes = 0;
    for (const PlyProperty& property : element.properties)
      element_bytes += header.format == PlyFormat::kAscii
                           ? 2
                           : (property.is_list() ? property.count_type.bytes : property.type.bytes);
    least_bytes += static_cast<double>(element.count) * std::max(element_bytes, 1);
    if (least_bytes > static_cast<double>(body_bytes) ||
        (element.name == "vertex" && element.count > INT_MAX))
      text.fail_at(element.line, header_claims(element, body_bytes));
  }
}

long long vertex_count(const PlyHeader& header) {
  for (const PlyElement& element : header.elements)
    if (element.name == "vertex") return element.count;
  return 0;
}

// Reads one element's properties: a vertex's x, y, z and a face's index list are kept.
class PlyElementReader {
 public:
  PlyElementReader(PlyBodyReader& body, const PlyElement& element, long long vertices,
                   std::size_t body_bytes)
      : body_(body), element_(element), vertices_(vertices), body_bytes_(body_bytes) {}

  void read(long long e, PolygonMesh& mesh) {
    Eigen::Vector3f position = Eigen::Vector3f::Zero();
    for (const PlyProperty& property : element_.properties) {
      if (!property.is_list()) {
        const double value = next(property.type, e);
        const int axis = property.name == "x"   ? 0
                         : property.name == "y" ? 1
                         : property.name == "z" ? 2
                                                : -1;
        if (axis >= 0) position[axis] = static_cast<float>(value);
        continue;
      }
      const double length = next(property.count_type, e);
      if (!(length >= 0 && length <= static_cast<double>(body_bytes_)) ||
          length != std::floor(length))
        body_.fail(element_.name + " " + std::to_string(e) + " has a list of " + text_of(length) +
                   " values");
      read_list(property, static_cast<long long>(length), e, mesh);
    }
    if (element_.name != "vertex") return;
    if (const auto defect = vertex_defect(position))
      body_.fail("vertex " + std::to_string(e) + " " + *defect);
    mesh.vertices.push_back(position);
  }

 private:
  void read_list(const PlyProperty& property, long long length, long long e, PolygonMesh& mesh) {
    const bool indices = is_index_list(element_, property);
    const std::size_t first_corner = mesh.corners.size();
    for (long long k = 0; k < length; ++k) {
      const double value = next(property.type, e);
      if (!indices) continue;
      if (!(value >= 0 && value < static_cast<double>(vertices_)) || value != std::floor(value))
        body_.fail("face " + std::to_string(e) + " indexes vertex " + text_of(value) +
                   ", the file has " + std::to_string(vertices_) + " vertices");
      mesh.corners.push_back(static_cast<int>(value));
    }
    if (!indices) return;
    // Points and edges bound no surface.
    if (length >= 3)
      mesh.face_corners.push_back(static_cast<int>(length));
    else
      mesh.corners.resize(first_corner);
  }

  double next(const PlyType& type, long long e) {
    const auto value = body_.value(type);
    if (!value)
      body_.fail("the data ends inside " + element_.name + " " + std::to_string(e) +
                 " (the header claims " + std::to_string(element_.count) + ")");
    return *value;
  }

  // A value read from the file, which may be any double; integers in full.
  static std::string text_of(double value) {
    if (value == std::floor(value) && std::abs(value) < 9e15)
      return std::to_string(static_cast<long long>(value));
    std::ostringstream text;
    text << value;
    return text.str();
  }

  PlyBodyReader& body_;
  const PlyElement& element_;
  long long vertices_;
  std::size_t body_bytes_;
};

}  // namespace

PolygonMesh read_ply_mesh(const std::filesystem::path& path) {
  MeshText text(path);
  const PlyHeader header = read_header(text);
  check_counts_fit(text, header);
  const long long vertices = vertex_count(header);
  PolygonMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(vertices));
  PlyBodyReader body(text, header);
  const std::size_t body_bytes = text.bytes().size() - header.body_offset;
  for (const PlyElement& element : header.elements) {
    if (element.properties.empty()) continue;  // nothing to read past
    if (element.name == "face") mesh.face_corners.reserve(static_cast<std::size_t>(element.count));
    PlyElementReader reader(body, element, vertices, body_bytes);
    for (long long e = 0; e < element.count; ++e) reader.read(e, mesh);
  }
  return mesh;
}

}  // namespace cosmos
