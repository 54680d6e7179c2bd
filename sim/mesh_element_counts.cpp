#include "sim/mesh_element_counts.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& reason) {
  throw InputError(path.string() + ": " + reason);
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string file_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) fail(path, "cannot open the mesh file");
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// Whitespace-separated tokens of a text body, a byte offset at a time.
class Tokens {
 public:
  Tokens(const std::string& text, std::size_t offset) : text_(text), at_(offset) {}
  std::optional<std::string> next() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    if (at_ >= text_.size()) return std::nullopt;
    const std::size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    return text_.substr(start, at_ - start);
  }
  // The rest of the current line, consumed.
  std::string line() {
    const std::size_t end = std::min(text_.find('\n', at_), text_.size());
    std::string rest = text_.substr(at_, end - at_);
    at_ = std::min(end + 1, text_.size());
    return rest;
  }
  bool at_end() const { return at_ >= text_.size(); }

 private:
  const std::string& text_;
  std::size_t at_;
};

std::optional<long long> integer(const std::string& token) {
  try {
    std::size_t used = 0;
    const long long value = std::stoll(token, &used);
    if (used == token.size()) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::optional<double> number(const std::string& token) {
  try {
    std::size_t used = 0;
    const double value = std::stod(token, &used);
    if (used == token.size()) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// A value read from the file, which may be any double.
std::string number_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string too_many(const std::string& what, long long count, std::size_t body_bytes) {
  return "header claims " + std::to_string(count) + " " + what + ", more than its " +
         std::to_string(body_bytes) + " bytes of data can hold";
}

std::string missing_vertex(long long face, long long index, long long vertices) {
  return "face " + std::to_string(face) + " indexes vertex " + std::to_string(index) +
         ", the file has " + std::to_string(vertices) + " vertices";
}

// ---- PLY ----

struct PlyProperty {
  std::string name;
  int bytes = 0;        // scalar size, or the list's item size
  int count_bytes = 0;  // > 0 for a list: the size of its count
  bool integer_type = false;
  bool count_signed = false;
  bool item_signed = false;
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

// Size in bytes and signedness of a PLY scalar type (0 for an unknown name).
std::pair<int, bool> ply_type(const std::string& name) {
  if (name == "char" || name == "int8") return {1, true};
  if (name == "uchar" || name == "uint8") return {1, false};
  if (name == "short" || name == "int16") return {2, true};
  if (name == "ushort" || name == "uint16") return {2, false};
  if (name == "int" || name == "int32") return {4, true};
  if (name == "uint" || name == "uint32") return {4, false};
  if (name == "float" || name == "float32") return {4, true};
  if (name == "double" || name == "float64") return {8, true};
  return {0, false};
}

bool ply_integer_type(const std::string& name) {
  return name != "float" && name != "float32" && name != "double" && name != "float64";
}

// Reads one value of a binary PLY body as a double (integers exactly up to 2^53).
class BinaryReader {
 public:
  BinaryReader(const std::string& bytes, std::size_t offset, bool big_endian)
      : bytes_(bytes), at_(offset), big_endian_(big_endian) {}
  std::optional<double> value(int size, bool is_signed, bool is_integer) {
    if (at_ + static_cast<std::size_t>(size) > bytes_.size()) return std::nullopt;
    std::uint64_t bits = 0;  // the value's bytes, least significant first
    for (int k = 0; k < size; ++k) {
      const auto byte = static_cast<unsigned char>(bytes_[at_ + static_cast<std::size_t>(k)]);
      const int shift = 8 * (big_endian_ ? size - 1 - k : k);
      bits |= static_cast<std::uint64_t>(byte) << shift;
    }
    at_ += static_cast<std::size_t>(size);
    if (!is_integer) {
      if (size == 4) {
        const auto low = static_cast<std::uint32_t>(bits);
        float f;
        std::memcpy(&f, &low, 4);
        return f;
      }
      double d;
      std::memcpy(&d, &bits, 8);
      return d;
    }
    if (is_signed && size < 8 && (bits >> (8 * size - 1)) != 0)
      return static_cast<double>(
          static_cast<std::int64_t>(bits | (~std::uint64_t{0} << (8 * size))));
    return static_cast<double>(bits);
  }

 private:
  const std::string& bytes_;
  std::size_t at_;
  bool big_endian_;
};

void check_ply(const fs::path& path, const std::string& bytes) {
  // assimp takes other spellings ("plY") and then loops on the body.
  if (bytes.rfind("ply\n", 0) != 0 && bytes.rfind("ply\r\n", 0) != 0)
    fail(path, "not a PLY file (its first line is not 'ply')");
  // The header ends at a line of its own (a line "element face 4end_header" is no end).
  std::size_t header_end = bytes.find("\nend_header");
  while (header_end != std::string::npos) {
    const std::size_t after = header_end + 11;
    if (after == bytes.size() || bytes[after] == '\n' || bytes[after] == '\r') break;
    header_end = bytes.find("\nend_header", after);
  }
  if (header_end == std::string::npos) fail(path, "PLY header has no end_header line");
  ++header_end;
  const std::size_t body = std::min(bytes.find('\n', header_end) + 1, bytes.size());
  std::istringstream header(bytes.substr(0, header_end));
  std::string line, format;
  std::vector<PlyElement> elements;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      words >> format;
    } else if (keyword == "element") {
      PlyElement element;
      std::string count;
      words >> element.name >> count;
      const auto value = integer(count);
      if (!value || *value < 0)
        fail(path, "element " + element.name + " has count '" + count + "'");
      element.count = *value;
      elements.push_back(element);
    } else if (keyword == "property") {
      if (elements.empty()) fail(path, "PLY property before any element");
      PlyProperty property;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string count_type, item_type;
        words >> count_type >> item_type >> property.name;
        property.count_bytes = ply_type(count_type).first;
        property.count_signed = ply_type(count_type).second;
        property.bytes = ply_type(item_type).first;
        property.item_signed = ply_type(item_type).second;
        property.integer_type = ply_integer_type(item_type);
        if (property.count_bytes == 0 || property.bytes == 0 || !ply_integer_type(count_type))
          fail(path, "property list " + count_type + " " + item_type + " has an unknown type");
      } else {
        words >> property.name;
        std::tie(property.bytes, property.item_signed) = ply_type(type);
        property.integer_type = ply_integer_type(type);
        if (property.bytes == 0) fail(path, "property " + type + " has an unknown type");
      }
      elements.back().properties.push_back(property);
    } else if (!keyword.empty() && keyword != "ply" && keyword != "comment" &&
               keyword != "obj_info") {
      // assimp skips what it does not know and can then loop on the body forever.
      fail(path, "PLY header line '" + line + "' is not a PLY header keyword");
    }
  }
  // What the reader takes from the file, declared as it expects: assimp reads a face element
  // without its index list, or vertices without x, y, z, past its buffers.
  for (const PlyElement& element : elements) {
    const auto has = [&](const char* name, bool list) {
      return std::any_of(
          element.properties.begin(), element.properties.end(),
          [&](const PlyProperty& p) { return p.name == name && (p.count_bytes > 0) == list; });
    };
    if (element.name == "vertex" && !(has("x", false) && has("y", false) && has("z", false)))
      fail(path, "PLY vertex element without properties x, y, z");
    if (element.name == "face" && !has("vertex_indices", true) && !has("vertex_index", true))
      fail(path, "PLY face element without a vertex_indices list");
  }
  const bool ascii = format == "ascii";
  // assimp reads a format it does not know by its first letters, trusting the counts.
  if (!ascii && format != "binary_little_endian" && format != "binary_big_endian")
    fail(path,
         "PLY format '" + format + "' is none of ascii, binary_little_endian, binary_big_endian");
  // The fewest bytes an element can take: its scalars and list counts (empty lists), or in
  // text one digit and one separator per value.
  const std::size_t body_bytes = bytes.size() - body;
  double least_bytes = 0;
  for (const PlyElement& element : elements) {
    int element_bytes = 0;
    for (const PlyProperty& property : element.properties)
      element_bytes +=
          ascii ? 2 : (property.count_bytes > 0 ? property.count_bytes : property.bytes);
    least_bytes += static_cast<double>(element.count) * std::max(element_bytes, 1);
    if (least_bytes > static_cast<double>(body_bytes))
      fail(path, too_many(element.name + " elements", element.count, body_bytes));
  }
  // Walk the body up to the faces, checking each index against the vertex count.
  long long vertices = 0;
  Tokens tokens(bytes, body);
  BinaryReader reader(bytes, body, format == "binary_big_endian");
  const auto read = [&](int size, bool is_signed, bool is_integer) -> std::optional<double> {
    if (!ascii) return reader.value(size, is_signed, is_integer);
    const auto token = tokens.next();
    return token ? number(*token) : std::nullopt;
  };
  for (const PlyElement& element : elements) {
    if (element.name == "vertex") vertices = element.count;
    const bool faces = element.name == "face";
    for (long long e = 0; e < element.count; ++e) {
      for (const PlyProperty& property : element.properties) {
        const auto truncated = [&] {
          fail(path, "data ends inside " + element.name + " " + std::to_string(e) +
                         " (the header claims " + std::to_string(element.count) + ")");
        };
        if (property.count_bytes == 0) {
          if (!read(property.bytes, property.item_signed, property.integer_type)) truncated();
          continue;
        }
        const auto length = read(property.count_bytes, property.count_signed, true);
        if (!length) truncated();
        if (!(*length >= 0 && *length <= static_cast<double>(body_bytes)) ||
            *length != std::floor(*length))
          fail(path, element.name + " " + std::to_string(e) + " has a list of " +
                         number_text(*length) + " values");
        const bool indices =
            faces && (property.name == "vertex_indices" || property.name == "vertex_index");
        for (long long k = 0; k < static_cast<long long>(*length); ++k) {
          const auto index = read(property.bytes, property.item_signed, property.integer_type);
          if (!index) truncated();
          if (indices && !(*index >= 0 && *index < static_cast<double>(vertices)))
            fail(path, "face " + std::to_string(e) + " indexes vertex " + number_text(*index) +
                           ", the file has " + std::to_string(vertices) + " vertices");
        }
      }
    }
    if (faces) return;
  }
}

// ---- OFF ----

// The next line holding data, as assimp reads them: comments (from '#') and empty lines are
// skipped, but a line of spaces or tabs is data to it (assimp read a face from one past its
// buffers), so it is returned here and refused as no vertex or face.
std::optional<std::string> data_line(Tokens& text) {
  while (!text.at_end()) {
    std::string line = text.line();
    const bool comment = line.find('#') != std::string::npos;
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") != std::string::npos) return line;
    if (!comment && line.find_first_not_of('\r') != std::string::npos) return line;
  }
  return std::nullopt;
}

void check_off(const fs::path& path, const std::string& bytes) {
  Tokens text(bytes, 0);
  auto first = data_line(text);
  if (!first) return;
  std::istringstream words(*first);
  std::string keyword;
  words >> keyword;
  std::string counts_line;
  if (keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0) {
    std::getline(words, counts_line);
    if (counts_line.find_first_not_of(" \t\r") == std::string::npos) {
      const auto next = data_line(text);
      if (!next) return;
      counts_line = *next;
    }
  } else {
    counts_line = *first;  // assimp reads a file without the OFF keyword from its counts
  }
  std::istringstream counts(counts_line);
  std::string vertex_token, face_token;
  counts >> vertex_token >> face_token;
  const auto vertices = integer(vertex_token), faces = integer(face_token);
  if (!vertices || !faces || *vertices < 0 || *faces < 0)
    fail(path, "OFF counts line '" + counts_line + "' is not two counts >= 0");
  // A vertex is at least "0 0 0\n", a face at least "0\n".
  const std::size_t body_bytes = bytes.size();
  if (static_cast<double>(*vertices) * 6 > static_cast<double>(body_bytes))
    fail(path, too_many("vertices", *vertices, body_bytes));
  if (static_cast<double>(*vertices) * 6 + static_cast<double>(*faces) * 2 >
      static_cast<double>(body_bytes))
    fail(path, too_many("faces", *faces, body_bytes));
  // Every line as the format has it: assimp parses garbage in a line as it can (and crashed
  // on a face line of non-digits).
  for (long long v = 0; v < *vertices; ++v) {
    const auto line = data_line(text);
    if (!line) fail(path, "ends inside vertex " + std::to_string(v));
    std::istringstream vertex(*line);
    std::string x, y, z;
    vertex >> x >> y >> z;
    if (!number(x) || !number(y) || !number(z))
      fail(path, "vertex " + std::to_string(v) + " is not three numbers: '" + *line + "'");
  }
  for (long long f = 0; f < *faces; ++f) {
    const auto line = data_line(text);
    if (!line) fail(path, "ends inside face " + std::to_string(f));
    std::istringstream face(*line);
    std::string token;
    face >> token;
    const auto corners = integer(token);
    // A face has 3 corners at least (assimp crashed on one of none).
    if (!corners || *corners < 3 || *corners > static_cast<long long>(body_bytes))
      fail(path, "face " + std::to_string(f) +
                     " does not start with a vertex count of 3 or more: '" + *line + "'");
    for (long long k = 0; k < *corners; ++k) {
      face >> token;
      const auto index = face ? integer(token) : std::nullopt;
      if (!index)
        fail(path, "face " + std::to_string(f) + " has fewer than " + std::to_string(*corners) +
                       " vertex indices");
      if (*index < 0 || *index >= *vertices) fail(path, missing_vertex(f, *index, *vertices));
    }
  }
}

}  // namespace

void check_mesh_element_counts(const fs::path& path) {
  const std::string extension = lowercase(path.extension().string());
  if (extension != ".ply" && extension != ".off") return;
  const std::string bytes = file_bytes(path);
  if (extension == ".ply")
    check_ply(path, bytes);
  else
    check_off(path, bytes);
}

}  // namespace cosmos
