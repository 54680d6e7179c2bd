#include "core/io/image_header.hpp"

#include <array>
#include <fstream>
#include <limits>

namespace cosmos {
namespace {

constexpr std::uint16_t kImageWidthTag = 256;
constexpr std::uint16_t kImageLengthTag = 257;
constexpr std::uint16_t kShortType = 3;
constexpr std::uint16_t kLongType = 4;
constexpr std::uint16_t kLong8Type = 16;

// Reads `bytes` (≤ 8) unsigned bytes at `offset` in the file's byte order.
class TiffBytes {
 public:
  explicit TiffBytes(const std::filesystem::path& path) : file_(path, std::ios::binary) {}

  bool start() {
    std::array<unsigned char, 4> head{};
    if (!read_at(0, head.data(), head.size())) return false;
    if (head[0] == 'I' && head[1] == 'I') {
      little_ = true;
    } else if (head[0] == 'M' && head[1] == 'M') {
      little_ = false;
    } else {
      return false;
    }
    const std::uint64_t version = number(2, 2).value_or(0);
    if (version == 42) {
      big_ = false;
      return true;
    }
    if (version == 43 && number(4, 2) == 8u) {
      big_ = true;
      return true;
    }
    return false;
  }

  bool big() const { return big_; }

  std::optional<std::uint64_t> number(std::uint64_t offset, int bytes) {
    std::array<unsigned char, 8> raw{};
    if (!read_at(offset, raw.data(), static_cast<std::size_t>(bytes))) return std::nullopt;
    std::uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) {
      const int index = little_ ? bytes - 1 - i : i;
      value = (value << 8) | raw[static_cast<std::size_t>(index)];
    }
    return value;
  }

 private:
  bool read_at(std::uint64_t offset, unsigned char* out, std::size_t bytes) {
    if (offset > static_cast<std::uint64_t>(std::numeric_limits<std::streamoff>::max()))
      return false;
    file_.clear();
    file_.seekg(static_cast<std::streamoff>(offset));
    file_.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(bytes));
    return file_.gcount() == static_cast<std::streamsize>(bytes);
  }

  std::ifstream file_;
  bool little_ = true;
  bool big_ = false;
};

}  // namespace

std::uint64_t ImageDimensions::pixels() const {
  if (width != 0 && height > std::numeric_limits<std::uint64_t>::max() / width)
    return std::numeric_limits<std::uint64_t>::max();
  return width * height;
}

std::optional<ImageDimensions> read_tiff_dimensions(const std::filesystem::path& file) {
  TiffBytes tiff(file);
  if (!tiff.start()) return std::nullopt;
  const int offset_bytes = tiff.big() ? 8 : 4;
  const int count_bytes = tiff.big() ? 8 : 2;
  const std::uint64_t entry_bytes = tiff.big() ? 20 : 12;
  const auto ifd = tiff.number(tiff.big() ? 8 : 4, offset_bytes);
  if (!ifd) return std::nullopt;
  const auto entries = tiff.number(*ifd, count_bytes);
  if (!entries) return std::nullopt;
  std::optional<std::uint64_t> width;
  std::optional<std::uint64_t> height;
  // The tags are sorted, so ImageWidth and ImageLength are among the first entries of a
  // well-formed IFD; a header claiming more entries than a file can hold stops at its end.
  for (std::uint64_t i = 0; i < *entries && !(width && height); ++i) {
    const std::uint64_t entry = *ifd + static_cast<std::uint64_t>(count_bytes) + i * entry_bytes;
    const auto tag = tiff.number(entry, 2);
    const auto type = tiff.number(entry + 2, 2);
    if (!tag || !type) return std::nullopt;
    if (*tag != kImageWidthTag && *tag != kImageLengthTag) continue;
    const std::uint64_t value_offset = entry + 4 + static_cast<std::uint64_t>(offset_bytes);
    std::optional<std::uint64_t> value;
    if (*type == kShortType) value = tiff.number(value_offset, 2);
    if (*type == kLongType) value = tiff.number(value_offset, 4);
    if (*type == kLong8Type && tiff.big()) value = tiff.number(value_offset, 8);
    if (!value) return std::nullopt;
    (*tag == kImageWidthTag ? width : height) = value;
  }
  if (!width || !height) return std::nullopt;
  return ImageDimensions{*width, *height};
}

std::optional<ImageDimensions> read_pfm_dimensions(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::array<char, 2> magic{};
  if (!in.read(magic.data(), magic.size())) return std::nullopt;
  if (magic[0] != 'P' || (magic[1] != 'f' && magic[1] != 'F')) return std::nullopt;
  ImageDimensions dimensions;
  if (!(in >> dimensions.width >> dimensions.height)) return std::nullopt;
  return dimensions;
}

}  // namespace cosmos
