#pragma once
// The model-base file: one versioned, checksummed file, read into memory once and used in
// place without parsing, so that a cell loads its base quickly and tells a stale or damaged
// base from a good one before using it: a fixed 32-byte header, then the FlatBuffers payload
// of core/io/model_base.fbs.
//
//   offset  size  field (little-endian)
//        0     8  magic "COSMOSMB"
//        8     4  format version (ModelBase::kFormatVersion; the header layout never changes)
//       12     4  header size in bytes (32)
//       16     8  payload size in bytes
//       24     8  XXH64 (seed 0) of the payload
//
// The payload is self-describing: it repeats the format version and holds the catalog content
// hash and the canonical parameters text the base was built with (core/io/parameters_text.hpp).
// Reading verifies everything before anything is used; every refusal is one InputError line
// `FILE: reason`, the reason starting with one of: "truncated", "corrupted", "format version",
// "built with other parameters" (naming the first differing key), or "not a COSMOS model
// base". A loaded base's registration streams live in the file's bytes, mapped read-only
// (zero copy).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "core/modelbase/model_base.hpp"

namespace cosmos {

inline constexpr std::size_t kModelBaseHeaderBytes = 32;

// Writes atomically (a temporary file beside `path`, then renamed): a reader never sees half a
// base. InputError naming the file when it cannot be written.
void write_model_base(const ModelBase& base, const std::filesystem::path& path);

// With expected_parameters_text, a base built with other parameters is refused.
ModelBase read_model_base(
    const std::filesystem::path& path,
    const std::optional<std::string>& expected_parameters_text = std::nullopt);

}  // namespace cosmos
