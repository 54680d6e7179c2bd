// Range image + sidecar (core/io/range_image_file.hpp). The input's first byte picks the
// image format (even: TIFF, odd: PFM); the next two give the sidecar's length (little-endian,
// wrapped to what is there); the sidecar's YAML text follows, then the image's bytes.
#include <cstddef>
#include <cstdint>

#include "core/input_error.hpp"
#include "core/io/range_image_file.hpp"
#include "fuzz/fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  const bool pfm = (data[0] & 1) != 0;
  const std::size_t rest = size - 3;
  const std::size_t sidecar_bytes =
      rest == 0 ? 0
                : (static_cast<std::size_t>(data[1]) | (std::size_t{data[2]} << 8)) % (rest + 1);
  cosmos::fuzz::write_input("range.yaml", data + 3, sidecar_bytes);
  const auto image = cosmos::fuzz::write_input(pfm ? "range.pfm" : "range.tiff",
                                               data + 3 + sidecar_bytes, rest - sidecar_bytes);
  try {
    cosmos::read_range_image(image);
  } catch (const cosmos::InputError&) {
  }
  return 0;
}
