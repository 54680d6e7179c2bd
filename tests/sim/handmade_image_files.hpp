#pragma once
// Writes the kinds of image file a range-image reader must reject (8/16-bit, 3-channel,
// float64) byte by byte: the test binaries do not see OpenCV's headers, and a hand-made
// baseline TIFF or PFM also pins exactly what the file holds.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace cosmos::testing {

enum class TiffSampleFormat : std::uint16_t { kUnsigned = 1, kFloat = 3 };

// An uncompressed little-endian baseline TIFF, one strip, 1 or 3 interleaved samples per
// pixel; the pixel bytes are all `fill_byte`.
inline void write_handmade_tiff(const std::filesystem::path& path, int width, int height,
                                int bits_per_sample, int samples_per_pixel,
                                TiffSampleFormat sample_format, std::uint8_t fill_byte = 0x40) {
  std::vector<std::uint8_t> bytes;
  auto put16 = [&](std::uint32_t v) {
    bytes.push_back(static_cast<std::uint8_t>(v & 0xff));
    bytes.push_back(static_cast<std::uint8_t>((v >> 8) & 0xff));
  };
  auto put32 = [&](std::uint32_t v) {
    put16(v & 0xffff);
    put16(v >> 16);
  };
  constexpr std::uint32_t kEntries = 11;
  constexpr std::uint32_t kIfdOffset = 8;
  constexpr std::uint32_t kArraysOffset = kIfdOffset + 2 + kEntries * 12 + 4;
  const std::uint32_t samples = static_cast<std::uint32_t>(samples_per_pixel);
  // With 3 samples the BitsPerSample and SampleFormat SHORT arrays follow the IFD.
  const std::uint32_t data_offset = kArraysOffset + 4 * samples;
  const std::uint32_t data_bytes = static_cast<std::uint32_t>(width) * height * samples *
                                   static_cast<std::uint32_t>(bits_per_sample) / 8;

  put16('I' | ('I' << 8));  // little-endian
  put16(42);
  put32(kIfdOffset);
  put16(kEntries);
  auto entry = [&](std::uint16_t tag, std::uint16_t type, std::uint32_t count,
                   std::uint32_t value) {
    put16(tag);
    put16(type);
    put32(count);
    if (type == 3 && count == 1) {
      put16(value);
      put16(0);
    } else {
      put32(value);
    }
  };
  constexpr std::uint16_t kShort = 3;
  constexpr std::uint16_t kLong = 4;
  const std::uint32_t bits = static_cast<std::uint32_t>(bits_per_sample);
  const std::uint32_t format = static_cast<std::uint32_t>(sample_format);
  entry(256, kLong, 1, static_cast<std::uint32_t>(width));
  entry(257, kLong, 1, static_cast<std::uint32_t>(height));
  entry(258, kShort, samples, samples == 1 ? bits : kArraysOffset);
  entry(259, kShort, 1, 1);                     // no compression
  entry(262, kShort, 1, samples == 3 ? 2 : 1);  // RGB or min-is-black
  entry(273, kLong, 1, data_offset);
  entry(277, kShort, 1, samples);
  entry(278, kLong, 1, static_cast<std::uint32_t>(height));
  entry(279, kLong, 1, data_bytes);
  entry(284, kShort, 1, 1);  // interleaved
  entry(339, kShort, samples, samples == 1 ? format : kArraysOffset + 2 * samples);
  put32(0);  // no further IFD
  for (std::uint32_t i = 0; i < samples; ++i) put16(bits);
  for (std::uint32_t i = 0; i < samples; ++i) put16(format);
  bytes.resize(bytes.size() + data_bytes, fill_byte);

  std::ofstream file(path, std::ios::binary);
  file.write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

// A PFM ("PF" = 3 channels, "Pf" = 1), little-endian (negative scale), all values `value`.
inline void write_handmade_pfm(const std::filesystem::path& path, int width, int height,
                               int channels, float value) {
  std::ofstream file(path, std::ios::binary);
  file << (channels == 3 ? "PF" : "Pf") << "\n" << width << " " << height << "\n-1.0\n";
  for (int i = 0; i < width * height * channels; ++i) {
    file.write(reinterpret_cast<const char*>(&value), sizeof value);
  }
}

// Only a TIFF's header and first IFD, with ImageWidth and ImageLength and no pixel data: what
// a crafted file claiming any size looks like. Classic or BigTIFF, either byte order; the
// dimensions as SHORT when they fit (as writers do), else LONG.
inline void write_tiff_header_only(const std::filesystem::path& path, std::uint32_t width,
                                   std::uint32_t height, bool big_endian, bool bigtiff) {
  std::vector<std::uint8_t> bytes;
  auto put = [&](std::uint64_t v, int count) {
    for (int i = 0; i < count; ++i) {
      const int shift = 8 * (big_endian ? count - 1 - i : i);
      bytes.push_back(static_cast<std::uint8_t>((v >> shift) & 0xff));
    }
  };
  const int offset_bytes = bigtiff ? 8 : 4;
  bytes.push_back(big_endian ? 'M' : 'I');
  bytes.push_back(big_endian ? 'M' : 'I');
  put(bigtiff ? 43 : 42, 2);
  if (bigtiff) {
    put(8, 2);
    put(0, 2);
  }
  put(bigtiff ? 16 : 8, offset_bytes);  // the first IFD follows the header
  put(3, bigtiff ? 8 : 2);
  auto entry = [&](std::uint16_t tag, std::uint32_t value) {
    const bool fits_short = value <= 0xffff;
    put(tag, 2);
    put(fits_short ? 3 : 4, 2);
    put(1, offset_bytes);
    put(value, fits_short ? 2 : 4);
    put(0, offset_bytes - (fits_short ? 2 : 4));
  };
  entry(254, 0);  // NewSubfileType, so the dimensions are not the first entry
  entry(256, width);
  entry(257, height);
  put(0, offset_bytes);
  std::ofstream file(path, std::ios::binary);
  file.write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

inline void write_text_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace cosmos::testing
