// The model-base payload (core/io/model_base_payload.hpp) behind a checksum that matches: the
// FlatBuffers verifier and the semantic range checks, then what the recognizer builds from a
// base it accepted (each part's distance field, core/recognition/part_pose_search.hpp). The
// header and checksum (core/io/model_base_file.hpp) are skipped: a random mutation would
// almost never pass them, a crafted file always does.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>

#include "core/io/model_base_payload.hpp"
#include "core/recognition/part_pose_search.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // FlatBuffers reads the payload in place, aligned as the file reader's block is; exactly
  // `size` bytes, so that AddressSanitizer sees any read past them.
  std::shared_ptr<std::uint8_t[]> payload(new std::uint8_t[std::max<std::size_t>(size, 1)]);
  if (size > 0) std::memcpy(payload.get(), data, size);
  cosmos::ModelBase base;
  if (cosmos::decode_model_base(payload.get(), size, payload, base)) return 0;
  // Small grids keep an iteration quick: a grid the reader accepted is bounded (at most
  // kMaxSurfaceVoxels), and the distance transform's cost only grows with it.
  for (int part = 0; part < static_cast<int>(base.parts.size()) && part < 8; ++part)
    if (base.parts[static_cast<std::size_t>(part)].surface_voxels.voxel_count() <= (1 << 18))
      cosmos::build_part_search_model(base, part);
  return 0;
}
