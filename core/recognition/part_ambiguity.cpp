#include "core/recognition/part_ambiguity.hpp"

#include <algorithm>

namespace cosmos {

PartAmbiguity judge_part_ambiguity(const RegistrationPoints& scene, const ModelBase& base,
                                   const PlacedCandidate& winner, const PlacedCandidate& rival,
                                   const RegistrationParameters& registration,
                                   const PartSupportParameters& support,
                                   const PartAmbiguityParameters& parameters,
                                   ModelSurfaces& surfaces) {
  PartAmbiguity judgement;
  if (scene.size() == 0) return judgement;
  std::vector<double> winner_mm, rival_mm;
  part_surface_distances(scene, base, winner.part_views, winner.view, winner.T_model_scene,
                         registration, support, surfaces, winner_mm);
  part_surface_distances(scene, base, rival.part_views, rival.view, rival.T_model_scene,
                         registration, support, surfaces, rival_mm);
  for (std::size_t i = 0; i < winner_mm.size() && i < rival_mm.size(); ++i) {
    const bool by_winner = winner_mm[i] <= support.inlier_distance_mm;
    const bool by_rival = rival_mm[i] <= support.inlier_distance_mm;
    judgement.winner_only_points += by_winner && !by_rival;
    judgement.rival_only_points += by_rival && !by_winner;
  }
  const auto contradicted = [&parameters](const PlacedCandidate& placed) {
    return std::max(0.0, 1 - placed.seen_fraction - parameters.contradiction_floor);
  };
  const double scene_points = scene.size();
  const double for_winner = judgement.winner_only_points / scene_points + contradicted(rival);
  const double for_rival = judgement.rival_only_points / scene_points + contradicted(winner);
  judgement.discriminating_fraction = for_winner + for_rival;
  judgement.discriminating_share =
      judgement.discriminating_fraction > 0 ? for_winner / judgement.discriminating_fraction : 0;
  judgement.ambiguous = judgement.discriminating_share < parameters.min_discriminating_share ||
                        judgement.discriminating_fraction < parameters.min_discriminating_fraction;
  return judgement;
}

}  // namespace cosmos
