#include "core/indexing/patch_pair_table.hpp"

namespace cosmos {
namespace {

struct KeyedPair {
  int key;
  IndexedPatchPair pair;
};

// Both orders of every pair of the view, each once.
void add_view_pairs(const ModelBaseView& view, const PatchPairKeyParameters& parameters,
                    std::vector<KeyedPair>& pairs) {
  const RigidTransform T_part_view = view.T_scanner_part.inverse();
  for_each_patch_pair(view.cosmos, parameters, [&](const Csmp& a, const Csmp& b) {
    for (const auto& [first, second] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
      const std::optional<PatchPairFeature> feature =
          patch_pair_feature(*first, *second, parameters);
      if (!feature) continue;
      const RigidTransform T_part_pair = T_part_view * feature->T_view_pair;
      pairs.push_back({patch_pair_key(*feature, parameters),
                       {Eigen::Quaterniond(T_part_pair.rotation).normalized().cast<float>(),
                        T_part_pair.translation_mm.cast<float>(), view.part_index}});
    }
  });
}

}  // namespace

PatchPairTable::PatchPairTable(const ModelBase& base, const PatchPairKeyParameters& parameters)
    : parameters_(parameters) {
  std::vector<KeyedPair> pairs;
  for (const ModelBaseView& view : base.views) add_view_pairs(view, parameters, pairs);
  // A counting sort by key: entries of one key keep the base's view order.
  first_of_key_.assign(static_cast<std::size_t>(parameters.key_count()) + 1, 0);
  for (const KeyedPair& pair : pairs) ++first_of_key_[static_cast<std::size_t>(pair.key) + 1];
  for (std::size_t k = 1; k < first_of_key_.size(); ++k) first_of_key_[k] += first_of_key_[k - 1];
  std::vector<std::uint32_t> next(first_of_key_.begin(), first_of_key_.end() - 1);
  entries_.resize(pairs.size());
  for (const KeyedPair& pair : pairs)
    entries_[next[static_cast<std::size_t>(pair.key)]++] = pair.pair;
}

}  // namespace cosmos
