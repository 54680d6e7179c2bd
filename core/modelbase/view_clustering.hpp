#pragma once
// View grouping (§4.4.2): complete-link agglomerative hierarchical clustering of an object's
// views by the dissimilarity of their shape-spectrum moment vectors (Eq. 4.3), the dendrogram
// it builds, its cut at a dissimilarity level (the thesis cuts at 0.1 or less) or at a
// requested number of clusters, and the centroids that summarize each view cluster.
//
// Cluster ids follow the usual dendrogram convention: the n views are clusters 0..n-1, and
// merge k creates cluster n + k. Each step merges the two clusters whose complete-link
// distance (the largest dissimilarity between their members) is smallest; equal distances
// are broken by the smaller cluster id pair (lowest first id, then lowest second id), so the
// result is the same on every machine. Complete-link heights never decrease.
#include <Eigen/Core>
#include <vector>

#include "core/representation/shape_spectrum.hpp"

namespace cosmos {

struct DendrogramMerge {
  int cluster_a = 0;  // the smaller id
  int cluster_b = 0;
  double height = 0;  // complete-link distance at which they merge
  int size = 0;       // views in the merged cluster
};

enum class ClusteringStatus { kOk, kNotSquare, kNotSymmetric, kInvalidValue, kEmpty };

struct Dendrogram {
  ClusteringStatus status = ClusteringStatus::kEmpty;
  int leaves = 0;
  std::vector<DendrogramMerge> merges;  // leaves - 1 merges, in order
};

// Dissimilarities must be finite, non-negative and symmetric (to 1e-12 relative); the
// diagonal is ignored. O(n^2) memory, O(n^3) time: fine for the 320 views of §4.5.
Dendrogram complete_link_clustering(const Eigen::MatrixXd& dissimilarity);

// Eq. 4.3 between every pair of moment vectors.
Eigen::MatrixXd spectral_dissimilarity_matrix(const std::vector<MomentVector>& moments);

// A partition as one label per view, clusters numbered 0.. in order of their lowest view.
struct ViewPartition {
  std::vector<int> label;
  int clusters = 0;
};

// Keeps the merges of height <= level: views closer than the level (complete-link) share a
// cluster.
ViewPartition cut_at_level(const Dendrogram& dendrogram, double level);

// Keeps the first leaves - clusters merges (clamped to 1..leaves clusters).
ViewPartition cut_to_count(const Dendrogram& dendrogram, int clusters);

// The mean moment vector of each cluster (§4.4.2's summary representation), all 11
// features averaged. `moments` must have one vector per label.
std::vector<MomentVector> cluster_centroids(const ViewPartition& partition,
                                            const std::vector<MomentVector>& moments);

}  // namespace cosmos
