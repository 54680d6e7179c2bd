#pragma once
// The FlatBuffers payload of the model-base file (core/io/model_base.fbs) to and from the
// in-memory ModelBase. Internal to core/io: model_base_file.cpp frames it with the header.
#include <flatbuffers/flatbuffers.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "core/modelbase/model_base.hpp"

namespace cosmos {

// Builds the payload into `builder` (finished, with the "CSMB" identifier). Deterministic:
// the same base gives the same bytes.
void encode_model_base(const ModelBase& base, flatbuffers::FlatBufferBuilder& builder);

// An upper bound of the payload size, to size the builder once and to refuse a base larger
// than FlatBuffers' 2 GiB offsets can address.
std::size_t estimated_payload_bytes(const ModelBase& base);

// Verifies (FlatBuffers Verifier and the base's own invariants: array lengths, indices in
// range, every value in range: core/modelbase/model_base_ranges.hpp) and decodes. The registration
// arrays of `out` point into `payload`, which `owner` keeps alive. Returns the reason the payload
// is corrupt, nullopt on success.
std::optional<std::string> decode_model_base(const std::uint8_t* payload, std::size_t payload_bytes,
                                             std::shared_ptr<const void> owner, ModelBase& out);

}  // namespace cosmos
