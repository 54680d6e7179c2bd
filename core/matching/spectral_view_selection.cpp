#include "core/matching/spectral_view_selection.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>
#include <numeric>

namespace cosmos {
namespace {

using MomentColumn = Eigen::Matrix<double, kSpectrumMoments, 1>;

MomentColumn column(const MomentVector& m) {
  MomentColumn c;
  for (int i = 0; i < kSpectrumMoments; ++i) c[i] = m[i];
  return c;
}

}  // namespace

SpectralViewSelector::SpectralViewSelector(const ModelBase& model_base,
                                           const SpectralSelectionParameters& parameters)
    : model_base_(model_base), parameters_(parameters) {
  inverse_covariance_.setIdentity();
  if (parameters.distance != SpectralDistance::kMahalanobis) return;
  // Pooled within-cluster covariance of the moment vectors, regularized so that moments that
  // never vary (a degenerate direction) do not blow up.
  Eigen::Matrix<double, kSpectrumMoments, kSpectrumMoments> covariance =
      Eigen::Matrix<double, kSpectrumMoments, kSpectrumMoments>::Zero();
  int samples = 0;
  for (const ViewCluster& cluster : model_base.clusters) {
    const MomentColumn centroid = column(cluster.centroid);
    for (int view : cluster.views) {
      const MomentColumn d = column(model_base.views[view].moments) - centroid;
      covariance += d * d.transpose();
      ++samples;
    }
  }
  if (samples > 1) covariance /= samples - 1;
  const double scale = std::max(covariance.trace() / kSpectrumMoments, 1e-30);
  covariance +=
      1e-6 * scale * Eigen::Matrix<double, kSpectrumMoments, kSpectrumMoments>::Identity();
  inverse_covariance_ = covariance.ldlt().solve(
      Eigen::Matrix<double, kSpectrumMoments, kSpectrumMoments>::Identity());
}

double SpectralViewSelector::distance(const MomentVector& a, const MomentVector& b) const {
  if (parameters_.distance == SpectralDistance::kEuclidean)
    return spectral_dissimilarity(a, b);  // Eq. 4.3
  const MomentColumn d = column(a) - column(b);
  return d.dot(inverse_covariance_ * d);
}

std::vector<int> SpectralViewSelector::rank_clusters(const MomentVector& moments) const {
  std::vector<double> distances(model_base_.clusters.size());
  for (std::size_t c = 0; c < distances.size(); ++c)
    distances[c] = distance(moments, model_base_.clusters[c].centroid);
  std::vector<int> order(distances.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return distances[a] < distances[b]; });
  return order;
}

std::vector<int> SpectralViewSelector::rank_parts(const MomentVector& moments) const {
  std::vector<double> closest(model_base_.parts.size(), std::numeric_limits<double>::infinity());
  for (const ModelBaseView& view : model_base_.views) {
    const auto part = static_cast<std::size_t>(view.part_index);
    closest[part] = std::min(closest[part], distance(moments, view.moments));
  }
  std::vector<int> order(closest.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return closest[a] < closest[b]; });
  return order;
}

std::vector<SpectralCandidate> SpectralViewSelector::select(const MomentVector& moments) const {
  std::vector<int> clusters = rank_clusters(moments);
  clusters.resize(std::min<std::size_t>(
      clusters.size(), static_cast<std::size_t>(std::max(parameters_.best_clusters, 0))));
  std::vector<SpectralCandidate> candidates;
  for (int cluster : clusters)
    for (int view : model_base_.clusters[cluster].views)
      candidates.push_back({view, cluster, distance(moments, model_base_.views[view].moments)});
  std::sort(candidates.begin(), candidates.end(),
            [](const SpectralCandidate& a, const SpectralCandidate& b) {
              return a.distance != b.distance ? a.distance < b.distance : a.view < b.view;
            });
  candidates.resize(std::min<std::size_t>(
      candidates.size(), static_cast<std::size_t>(std::max(parameters_.best_views, 0))));
  return candidates;
}

}  // namespace cosmos
