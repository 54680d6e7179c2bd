#include "core/modelbase/view_grouping.hpp"

namespace cosmos {

ViewGroupingResult group_model_views(const ModelBase& base,
                                     const ViewGroupingParameters& parameters) {
  ViewGroupingResult result;
  for (int part = 0; part < static_cast<int>(base.parts.size()); ++part) {
    std::vector<int> members;
    std::vector<MomentVector> moments;
    for (int v = 0; v < static_cast<int>(base.views.size()); ++v) {
      const ModelBaseView& view = base.views[static_cast<std::size_t>(v)];
      if (view.part_index != part) continue;
      members.push_back(v);
      moments.push_back(view.moments);
    }
    if (members.empty()) continue;
    const Dendrogram dendrogram = complete_link_clustering(spectral_dissimilarity_matrix(moments));
    if (dendrogram.status != ClusteringStatus::kOk) {
      result.status = dendrogram.status;
      result.failed_part = part;
      result.clusters.clear();
      return result;
    }
    const ViewPartition partition = parameters.cluster_count > 0
                                        ? cut_to_count(dendrogram, parameters.cluster_count)
                                        : cut_at_level(dendrogram, parameters.cut_level);
    const std::vector<MomentVector> centroids = cluster_centroids(partition, moments);
    const std::size_t first = result.clusters.size();
    for (int c = 0; c < partition.clusters; ++c)
      result.clusters.push_back({part, {}, centroids[static_cast<std::size_t>(c)]});
    for (std::size_t k = 0; k < members.size(); ++k)
      result.clusters[first + static_cast<std::size_t>(partition.label[k])].views.push_back(
          members[k]);
  }
  return result;
}

}  // namespace cosmos
