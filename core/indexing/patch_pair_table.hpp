#pragma once
// Every CSMP pair of every model view (patch_pair_key.hpp), both orders, filed under
// its key: the catalog-wide index the recognizer votes with (pose_voting.hpp). A dense table
// of key_count() slots (compressed rows: the entries of key k are first_of_key[k] ..
// first_of_key[k + 1]), so a lookup is two reads and its entries lie side by side. Each entry
// keeps the pair's frame in its part's frame, so votes from different views of one part for
// one pose of it fall together.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/indexing/patch_pair_key.hpp"
#include "core/modelbase/model_base.hpp"

namespace cosmos {

struct IndexedPatchPair {
  Eigen::Quaternionf q_part_pair;  // rotation of the pair's frame in the part frame
  Eigen::Vector3f t_part_pair_mm;  // its origin in the part frame
  std::int32_t part = 0;           // index into ModelBase::parts
};

class PatchPairTable {
 public:
  PatchPairTable() = default;
  PatchPairTable(const ModelBase& base, const PatchPairKeyParameters& parameters);

  std::span<const IndexedPatchPair> entries(int key) const {
    const auto k = static_cast<std::size_t>(key);
    return {entries_.data() + first_of_key_[k], first_of_key_[k + 1] - first_of_key_[k]};
  }
  std::size_t size() const { return entries_.size(); }
  std::size_t memory_bytes() const {
    return entries_.size() * sizeof(IndexedPatchPair) +
           first_of_key_.size() * sizeof(std::uint32_t);
  }
  const PatchPairKeyParameters& key_parameters() const { return parameters_; }

 private:
  PatchPairKeyParameters parameters_;
  std::vector<std::uint32_t> first_of_key_;
  std::vector<IndexedPatchPair> entries_;
};

}  // namespace cosmos
