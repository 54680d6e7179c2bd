#include "core/recognition/confusable_parts.hpp"

#include <algorithm>

#include "core/modelbase/model_surface.hpp"

namespace cosmos {

std::vector<int> confusion_probe_views(const PartSearchModel& part, int views_per_part) {
  const std::size_t count = part.views.size();
  const std::size_t probes = std::min(count, static_cast<std::size_t>(std::max(views_per_part, 0)));
  std::vector<int> views;
  for (std::size_t k = 0; k < probes; ++k) views.push_back(part.views[k * count / probes]);
  return views;
}

std::vector<std::vector<int>> find_confusable_parts(const ModelBase& base,
                                                    std::span<const PartSearchModel> models,
                                                    const ConfusablePartParameters& parameters,
                                                    const TaskRunner& tasks) {
  const int part_count = static_cast<int>(base.parts.size());
  std::vector<std::vector<int>> confusable(static_cast<std::size_t>(part_count));
  if (!parameters.enabled) return confusable;
  std::vector<PartExtent> extents;
  for (const ModelPart& part : base.parts) extents.push_back(part_extent(part));
  std::vector<int> probes;
  for (const PartSearchModel& model : models)
    for (int view : confusion_probe_views(model, parameters.views_per_part)) probes.push_back(view);
  // Per probe view, the parts that explain it.
  std::vector<std::vector<int>> explaining(probes.size());
  const RangeImage no_image;
  tasks.run(static_cast<int>(probes.size()), [&](int probe) {
    const ModelBaseView& view = base.views[static_cast<std::size_t>(probes[probe])];
    const ModelSurface surface(view);
    const RegistrationPoints& points = surface.points();
    // The view is one part seen whole, not on the belt: only the extent bound holds.
    const SceneExtent extent = scene_extent(points, no_image);
    const QuickFitPoints quick_points = quick_fit_points(points, parameters.quick_fit);
    const ViewSizeGate views =
        view_size_gate(extent, SceneParts::kOne, false, parameters.size_gate);
    for (int part = 0; part < part_count; ++part) {
      if (part == view.part_index ||
          judge_part_size(extents[static_cast<std::size_t>(part)], extent, SceneParts::kOne, false,
                          parameters.size_gate) != SizeVerdict::kFits)
        continue;
      const std::vector<FieldHypothesis> fits =
          quick_field_poses(quick_points, base, models[static_cast<std::size_t>(part)],
                            parameters.search, parameters.quick_fit, views);
      if (!fits.empty() && fits.front().truncated_mean_square_mm2 <= parameters.close_fit_mm2)
        explaining[static_cast<std::size_t>(probe)].push_back(part);
    }
  });
  for (std::size_t probe = 0; probe < probes.size(); ++probe) {
    const int viewed_part = base.views[static_cast<std::size_t>(probes[probe])].part_index;
    for (int part : explaining[probe]) {
      confusable[static_cast<std::size_t>(part)].push_back(viewed_part);
      confusable[static_cast<std::size_t>(viewed_part)].push_back(part);
    }
  }
  for (std::vector<int>& parts : confusable) {
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
  }
  return confusable;
}

}  // namespace cosmos
