#include "realtime/cell/piece_explained.hpp"

namespace cosmos {

bool piece_explained_by(const std::vector<Eigen::Vector3d>& points_loop_mm,
                        const std::vector<PartInLoop>& parts,
                        const PartRecognitionContext& context) {
  if (points_loop_mm.empty()) return false;
  for (const PartInLoop& part : parts) {
    const PartDistanceField& field = context.recognizer->part_search_model(part.part).field;
    const RigidTransform T_part_loop = part.T_loop_part.inverse();
    std::size_t on_surface = 0;
    for (const Eigen::Vector3d& point : points_loop_mm)
      on_surface +=
          field.distance_mm(T_part_loop.apply(point)) <= context.blob.explained_distance_mm ? 1 : 0;
    if (static_cast<double>(on_surface) >=
        kExplainedFraction * static_cast<double>(points_loop_mm.size()))
      return true;
  }
  return false;
}

}  // namespace cosmos
