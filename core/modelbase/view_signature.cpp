#include "core/modelbase/view_signature.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/modelbase/model_base.hpp"
#include "core/modelbase/model_surface.hpp"

namespace cosmos {
namespace {

using Signature = ViewSignature;
constexpr int kSpanStart = Signature::kHeightBins + Signature::kRadiusBins;

int bin_of(double value_mm, int bins) {
  return std::clamp(static_cast<int>(value_mm / Signature::kBinMm), 0, bins - 1);
}

// Counts per bin, starting at `first`, turned into cumulative fractions of kWhole.
void accumulate(const std::array<double, Signature::kBins>& counts, int first, int bins,
                double total, Signature& signature) {
  double running = 0;
  for (int k = first; k < first + bins; ++k) {
    running += counts[static_cast<std::size_t>(k)];
    signature.cumulative[static_cast<std::size_t>(k)] =
        static_cast<std::uint16_t>(std::lround(Signature::kWhole * std::min(1.0, running / total)));
  }
}

}  // namespace

ViewSignature view_signature(const Eigen::Matrix3Xd& positions_mm, double base_height_mm) {
  Signature signature;
  const Eigen::Index count = positions_mm.cols();
  if (count == 0) return signature;
  std::array<double, Signature::kBins> counts{};
  const Eigen::Vector2d centroid = positions_mm.topRows<2>().rowwise().mean();
  for (Eigen::Index i = 0; i < count; ++i) {
    const double height_mm = positions_mm(2, i) - base_height_mm;
    const double radius_mm = (positions_mm.col(i).head<2>() - centroid).norm();
    counts[static_cast<std::size_t>(bin_of(height_mm, Signature::kHeightBins))] += 1;
    counts[static_cast<std::size_t>(Signature::kHeightBins +
                                    bin_of(radius_mm, Signature::kRadiusBins))] += 1;
  }
  accumulate(counts, 0, Signature::kHeightBins, static_cast<double>(count), signature);
  accumulate(counts, Signature::kHeightBins, Signature::kRadiusBins, static_cast<double>(count),
             signature);
  // Points are in grid order, so every step-th one is an even subset.
  const Eigen::Index kept = std::min<Eigen::Index>(count, Signature::kSpanPoints);
  const auto subset = [&](Eigen::Index k) { return positions_mm.col(k * count / kept); };
  double pairs = 0;
  for (Eigen::Index a = 0; a < kept; ++a)
    for (Eigen::Index b = a + 1; b < kept; ++b) {
      counts[static_cast<std::size_t>(
          kSpanStart + bin_of((subset(a) - subset(b)).norm(), Signature::kSpanBins))] += 1;
      pairs += 1;
    }
  if (pairs == 0) {
    // One point: its only span is zero.
    counts[kSpanStart] = 1;
    pairs = 1;
  }
  accumulate(counts, kSpanStart, Signature::kSpanBins, pairs, signature);
  return signature;
}

double signature_distance_mm(const ViewSignature& a, const ViewSignature& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  std::int64_t area = 0;
  for (int k = 0; k < Signature::kBins; ++k)
    area += std::abs(static_cast<int>(a.cumulative[static_cast<std::size_t>(k)]) -
                     static_cast<int>(b.cumulative[static_cast<std::size_t>(k)]));
  return static_cast<double>(area) * Signature::kBinMm / Signature::kWhole;
}

bool is_cumulative(const ViewSignature& signature) {
  if (signature.empty())
    return std::all_of(signature.cumulative.begin(), signature.cumulative.end(),
                       [](std::uint16_t value) { return value == 0; });
  for (const auto& [first, bins] : {std::pair{0, Signature::kHeightBins},
                                    std::pair{Signature::kHeightBins, Signature::kRadiusBins},
                                    std::pair{kSpanStart, Signature::kSpanBins}}) {
    const auto begin = signature.cumulative.begin() + first;
    if (!std::is_sorted(begin, begin + bins) || *(begin + bins - 1) != Signature::kWhole)
      return false;
  }
  return true;
}

void summarize_view_signatures(ModelBase& base, int part) {
  const std::vector<Eigen::Vector3d>& hull =
      base.parts[static_cast<std::size_t>(part)].hull_vertices_mm;
  for (ModelBaseView& view : base.views) {
    if (view.part_index != part) continue;
    const ModelSurface surface(view);
    const Eigen::Matrix3Xd& positions_mm = surface.points().position_mm;
    // Without a hull, the lowest control point stands in for the part's lowest point.
    double lowest_mm = positions_mm.cols() > 0 ? positions_mm.row(2).minCoeff() : 0.0;
    for (const Eigen::Vector3d& corner : hull)
      lowest_mm = std::min(lowest_mm, view.T_scanner_part.apply(corner).z());
    view.signature = view_signature(positions_mm, lowest_mm);
  }
}

}  // namespace cosmos
