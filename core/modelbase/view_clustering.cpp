#include "core/modelbase/view_clustering.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace cosmos {
namespace {

ClusteringStatus check_matrix(const Eigen::MatrixXd& d) {
  if (d.rows() != d.cols()) return ClusteringStatus::kNotSquare;
  if (d.rows() == 0) return ClusteringStatus::kEmpty;
  for (Eigen::Index i = 0; i < d.rows(); ++i)
    for (Eigen::Index j = 0; j < d.cols(); ++j) {
      if (i == j) continue;
      if (!std::isfinite(d(i, j)) || d(i, j) < 0) return ClusteringStatus::kInvalidValue;
      if (std::abs(d(i, j) - d(j, i)) > 1e-12 * std::max(1.0, std::abs(d(i, j))))
        return ClusteringStatus::kNotSymmetric;
    }
  return ClusteringStatus::kOk;
}

// Union-find over the views, applying the first `merge_count` merges.
ViewPartition partition_after(const Dendrogram& dendrogram, std::size_t merge_count) {
  const int n = dendrogram.leaves;
  // Each cluster id (leaf or merge) points at a representative view.
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> representative(static_cast<std::size_t>(n) + dendrogram.merges.size());
  std::iota(representative.begin(), representative.begin() + n, 0);
  auto find = [&parent](int v) {
    while (parent[static_cast<std::size_t>(v)] != v) v = parent[static_cast<std::size_t>(v)];
    return v;
  };
  for (std::size_t k = 0; k < merge_count; ++k) {
    const DendrogramMerge& m = dendrogram.merges[k];
    const int ra = find(representative[static_cast<std::size_t>(m.cluster_a)]);
    const int rb = find(representative[static_cast<std::size_t>(m.cluster_b)]);
    parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    representative[static_cast<std::size_t>(n) + k] = std::min(ra, rb);
  }
  // Roots are each cluster's lowest view, so scanning views in order numbers the clusters
  // by their lowest view.
  ViewPartition partition;
  partition.label.assign(static_cast<std::size_t>(n), -1);
  std::vector<int> root_label(static_cast<std::size_t>(n), -1);
  for (int v = 0; v < n; ++v) {
    int& label = root_label[static_cast<std::size_t>(find(v))];
    if (label < 0) label = partition.clusters++;
    partition.label[static_cast<std::size_t>(v)] = label;
  }
  return partition;
}

}  // namespace

Dendrogram complete_link_clustering(const Eigen::MatrixXd& dissimilarity) {
  Dendrogram dendrogram;
  dendrogram.status = check_matrix(dissimilarity);
  if (dendrogram.status != ClusteringStatus::kOk) return dendrogram;
  const int n = static_cast<int>(dissimilarity.rows());
  dendrogram.leaves = n;
  // Active clusters by slot: slot s holds cluster id[s]; a union takes the slot of its first
  // part, the other slot is retired.
  Eigen::MatrixXd distance = dissimilarity;
  std::vector<int> id(static_cast<std::size_t>(n)), size(static_cast<std::size_t>(n), 1);
  std::iota(id.begin(), id.end(), 0);
  std::vector<int> active_slots(id);
  const auto id_pair = [&id](int s, int t) {
    return std::pair<int, int>(
        std::minmax(id[static_cast<std::size_t>(s)], id[static_cast<std::size_t>(t)]));
  };
  for (int k = 0; k < n - 1; ++k) {
    int best_s = -1, best_t = -1;
    double best = std::numeric_limits<double>::infinity();
    std::pair<int, int> best_ids;
    for (std::size_t a = 0; a < active_slots.size(); ++a) {
      for (std::size_t b = a + 1; b < active_slots.size(); ++b) {
        const int s = active_slots[a], t = active_slots[b];
        const double d = distance(s, t);
        if (best_s >= 0 && d > best) continue;
        const std::pair<int, int> ids = id_pair(s, t);
        if (best_s < 0 || d < best || ids < best_ids) {
          best = d;
          best_s = s;
          best_t = t;
          best_ids = ids;
        }
      }
    }
    const int merged_size =
        size[static_cast<std::size_t>(best_s)] + size[static_cast<std::size_t>(best_t)];
    dendrogram.merges.push_back({best_ids.first, best_ids.second, best, merged_size});
    // Complete link (§4.4.2): the distance to the union is the larger of the two.
    for (int r : active_slots) {
      if (r == best_s || r == best_t) continue;
      const double d = std::max(distance(best_s, r), distance(best_t, r));
      distance(best_s, r) = distance(r, best_s) = d;
    }
    active_slots.erase(std::find(active_slots.begin(), active_slots.end(), best_t));
    id[static_cast<std::size_t>(best_s)] = n + k;
    size[static_cast<std::size_t>(best_s)] = merged_size;
  }
  return dendrogram;
}

Eigen::MatrixXd spectral_dissimilarity_matrix(const std::vector<MomentVector>& moments) {
  const auto n = static_cast<Eigen::Index>(moments.size());
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j)
      d(i, j) = d(j, i) = spectral_dissimilarity(moments[static_cast<std::size_t>(i)],
                                                 moments[static_cast<std::size_t>(j)]);
  return d;
}

ViewPartition cut_at_level(const Dendrogram& dendrogram, double level) {
  std::size_t count = 0;
  while (count < dendrogram.merges.size() && dendrogram.merges[count].height <= level) ++count;
  return partition_after(dendrogram, count);
}

ViewPartition cut_to_count(const Dendrogram& dendrogram, int clusters) {
  if (dendrogram.leaves == 0) return {};
  const int kept = std::clamp(clusters, 1, dendrogram.leaves);
  return partition_after(dendrogram, static_cast<std::size_t>(dendrogram.leaves - kept));
}

std::vector<MomentVector> cluster_centroids(const ViewPartition& partition,
                                            const std::vector<MomentVector>& moments) {
  std::vector<MomentVector> centroids(static_cast<std::size_t>(partition.clusters), MomentVector{});
  std::vector<int> count(static_cast<std::size_t>(partition.clusters), 0);
  const std::size_t n = std::min(partition.label.size(), moments.size());
  for (std::size_t v = 0; v < n; ++v) {
    const auto c = static_cast<std::size_t>(partition.label[v]);
    for (std::size_t f = 0; f < moments[v].size(); ++f) centroids[c][f] += moments[v][f];
    ++count[c];
  }
  for (std::size_t c = 0; c < centroids.size(); ++c)
    if (count[c] > 0)
      for (double& f : centroids[c]) f /= count[c];
  return centroids;
}

}  // namespace cosmos
