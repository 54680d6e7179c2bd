#pragma once
// The pixel dimensions an image file declares in its header, read without decoding it: a
// reader checks them against its limit before a decoder allocates what a crafted header
// claims. TIFF (classic and BigTIFF, either byte order: the first IFD's ImageWidth and
// ImageLength) and PFM ("Pf"/"PF", width, height).
#include <cstdint>
#include <filesystem>
#include <optional>

namespace cosmos {

struct ImageDimensions {
  std::uint64_t width = 0;
  std::uint64_t height = 0;
  std::uint64_t pixels() const;  // saturates instead of wrapping
};

// Nullopt when the header does not state both dimensions; the decoder then reports the file.
std::optional<ImageDimensions> read_tiff_dimensions(const std::filesystem::path& file);
std::optional<ImageDimensions> read_pfm_dimensions(const std::filesystem::path& file);

}  // namespace cosmos
