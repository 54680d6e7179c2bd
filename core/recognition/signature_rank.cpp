#include "core/recognition/signature_rank.hpp"

#include <algorithm>
#include <limits>

namespace cosmos {

std::vector<PartSignatureDistance> rank_by_signature(const ViewSignature& scene,
                                                     std::span<const int> parts,
                                                     const ModelBase& base,
                                                     std::span<const PartSearchModel> models) {
  std::vector<PartSignatureDistance> ranked;
  ranked.reserve(parts.size());
  for (const int part : parts) {
    double closest_mm = std::numeric_limits<double>::infinity();
    for (const int view : models[static_cast<std::size_t>(part)].views)
      closest_mm = std::min(
          closest_mm,
          signature_distance_mm(scene, base.views[static_cast<std::size_t>(view)].signature));
    ranked.push_back({part, closest_mm});
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const PartSignatureDistance& a, const PartSignatureDistance& b) {
                     return a.distance_mm < b.distance_mm;
                   });
  return ranked;
}

std::size_t parts_fitted_first(std::span<const PartSignatureDistance> ranked,
                               const SignatureRankParameters& parameters) {
  if (ranked.empty()) return 0;
  const double within_mm = parameters.ratio * ranked.front().distance_mm;
  std::size_t fitted = std::min(ranked.size(), static_cast<std::size_t>(parameters.min_parts));
  while (fitted < ranked.size() && ranked[fitted].distance_mm <= within_mm) ++fitted;
  return fitted;
}

}  // namespace cosmos
