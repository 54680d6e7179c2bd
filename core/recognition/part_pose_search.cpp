#include "core/recognition/part_pose_search.hpp"

#include <algorithm>
#include <initializer_list>
#include <limits>
#include <set>

#include "core/modelbase/model_surface.hpp"
#include "core/recognition/pose_hypotheses.hpp"

namespace cosmos {
namespace {

// One stage of the field search: every hypothesis `iterations` alignment steps in the field
// (none: scored as it is) on `points`, then the best `keep` of them (kKeepAll: all, sorted).
constexpr std::size_t kKeepAll = std::numeric_limits<std::size_t>::max();
struct FieldStage {
  const RegistrationPoints& points;
  int iterations = 0;
  std::size_t keep = 0;
};

// Fewer hypotheses than this per share are not worth handing to another thread.
constexpr int kMinHypothesesPerShare = 32;

// The stages in turn (each on fewer hypotheses, most of them on more points): best first at the
// end; ties keep generation order (views in base order, turns by angle). Each stage's
// hypotheses are aligned and scored in contiguous shares on `tasks`.
void run_field_stages(const PartDistanceField& field, const BeltContact& belt, double truncation_mm,
                      std::initializer_list<FieldStage> stages,
                      std::vector<FieldHypothesis>& hypotheses, const TaskRunner& tasks) {
  std::vector<std::vector<double>> kept_scores;  // per share, a max-heap of its best scores
  std::vector<std::size_t> order;
  std::vector<FieldHypothesis> kept;
  for (const FieldStage& stage : stages) {
    const std::size_t keep = std::min(stage.keep, hypotheses.size());
    // A stage that only scores keeps the best few of many: a start whose partial sum already
    // exceeds the keep-th best score its share has seen cannot be among the best `keep` of
    // all, and is scored no further (its value is then some value above that bound). The
    // others' scores are exact, so the kept ones do not depend on the shares.
    const bool abandon = stage.iterations == 0 && keep > 0 && keep < hypotheses.size();
    const int count = static_cast<int>(hypotheses.size());
    const int shares = share_count(tasks, count, kMinHypothesesPerShare);
    kept_scores.resize(static_cast<std::size_t>(shares));
    run_in_shares(tasks, count, shares, [&](int share, int begin, int end) {
      std::vector<double>& heap = kept_scores[static_cast<std::size_t>(share)];
      heap.clear();
      for (int k = begin; k < end; ++k) {
        FieldHypothesis& hypothesis = hypotheses[static_cast<std::size_t>(k)];
        if (stage.iterations > 0)
          hypothesis.T_part_scene = align_in_distance_field(
              stage.points, field, hypothesis.T_part_scene, stage.iterations, truncation_mm, belt);
        const double bound =
            abandon && heap.size() == keep ? heap.front() : std::numeric_limits<double>::infinity();
        hypothesis.truncated_mean_square_mm2 = field_truncated_mean_square_mm2(
            stage.points, field, hypothesis.T_part_scene, truncation_mm, bound);
        if (!abandon || hypothesis.truncated_mean_square_mm2 > bound) continue;
        heap.push_back(hypothesis.truncated_mean_square_mm2);
        std::push_heap(heap.begin(), heap.end());
        if (heap.size() > keep) {
          std::pop_heap(heap.begin(), heap.end());
          heap.pop_back();
        }
      }
    });
    // The best `keep` by score, ties in generation order (a stable sort's order), moved once.
    order.resize(hypotheses.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    const auto better = [&hypotheses](std::size_t a, std::size_t b) {
      const double score_a = hypotheses[a].truncated_mean_square_mm2;
      const double score_b = hypotheses[b].truncated_mean_square_mm2;
      return score_a < score_b || (score_a == score_b && a < b);
    };
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(keep), order.end(),
                      better);
    kept.clear();
    for (std::size_t k = 0; k < keep; ++k) kept.push_back(hypotheses[order[k]]);
    hypotheses.swap(kept);
  }
}

// Turns about the viewing axis of every start view the scene's extent fits, the scene's
// centroid on the view's: as part-frame poses.
std::vector<FieldHypothesis> turned_view_starts(const RegistrationPoints& scoring,
                                                const ModelBase& base, const PartSearchModel& model,
                                                int turns, const ViewSizeGate& gate) {
  const Eigen::Vector3d scene_centre = scoring.position_mm.rowwise().mean();
  std::vector<FieldHypothesis> starts;
  for (const std::size_t s : model.start_views) {
    const ModelBaseView& view = base.views[static_cast<std::size_t>(model.views[s])];
    if (!gate.fits(view.extent)) continue;
    const Eigen::Vector3d& model_centre = model.view_centroid_mm[s];
    const RigidTransform T_part_view = view.T_scanner_part.inverse();
    for (int k = 0; k < turns; ++k)
      starts.push_back({T_part_view * in_plane_turn(k, turns, scene_centre, model_centre), 0.0});
  }
  return starts;
}

// Starts that converged to one pose of the part (on one view or neighbouring ones) are one
// hypothesis, and one that fits the part much worse than the best is none: the caller
// registers each. `sorted`: best first.
std::vector<ViewPoseHypothesis> distinct_hypotheses(const ModelBase& base,
                                                    const std::vector<ViewPoseHypothesis>& sorted,
                                                    const PartPoseSearchParameters& parameters,
                                                    int count) {
  const auto T_part_scene = [&base](const ViewPoseHypothesis& hypothesis) {
    return base.views[static_cast<std::size_t>(hypothesis.view)].T_scanner_part.inverse() *
           hypothesis.T_model_scene;
  };
  std::vector<ViewPoseHypothesis> distinct;
  std::vector<RigidTransform> distinct_poses;
  for (const ViewPoseHypothesis& hypothesis : sorted) {
    if (distinct.size() >= static_cast<std::size_t>(count)) break;
    if (hypothesis.truncated_mean_square_mm2 >
        parameters.worst_kept_score_mm2(sorted.front().truncated_mean_square_mm2))
      break;
    const RigidTransform pose = T_part_scene(hypothesis);
    const bool repeated =
        std::any_of(distinct_poses.begin(), distinct_poses.end(), [&](const RigidTransform& kept) {
          return rotation_angle_between_rad(kept.rotation, pose.rotation) <
                     parameters.same_pose_rad &&
                 (kept.translation_mm - pose.translation_mm).norm() < parameters.same_pose_mm;
        });
    if (repeated) continue;
    distinct.push_back(hypothesis);
    distinct_poses.push_back(pose);
  }
  return distinct;
}

}  // namespace

int nearest_view(const ModelBase& base, const PartSearchModel& model,
                 const RigidTransform& T_part_scene) {
  const Eigen::Vector3d seen_from_part = T_part_scene.rotation * Eigen::Vector3d::UnitZ();
  int nearest = -1;
  double nearest_cosine = 0;
  for (const int v : model.views) {
    const double cosine =
        base.views[static_cast<std::size_t>(v)].direction_part.dot(seen_from_part);
    if (nearest < 0 || cosine > nearest_cosine) {
      nearest = v;
      nearest_cosine = cosine;
    }
  }
  return nearest;
}

PartSearchModel build_part_search_model(const ModelBase& base, int part) {
  PartSearchModel model;
  bool has_coarse_views = false;
  for (const ModelBaseView& view : base.views)
    has_coarse_views |= view.part_index == part && is_once_subdivided_view(view.view_index);
  for (std::size_t v = 0; v < base.views.size(); ++v) {
    const ModelBaseView& view = base.views[v];
    if (view.part_index != part || view.control_point_count() == 0) continue;
    if (!has_coarse_views || is_once_subdivided_view(view.view_index))
      model.start_views.push_back(model.views.size());
    model.views.push_back(static_cast<int>(v));
    model.view_centroid_mm.push_back(view.control_point_centroid_mm);
  }
  const ModelPart& model_part = base.parts[static_cast<std::size_t>(part)];
  model.field = PartDistanceField(model_part.surface_voxels);
  model.surface_sample_mm.resize(3, static_cast<Eigen::Index>(model_part.surface_sample_mm.size()));
  for (std::size_t i = 0; i < model_part.surface_sample_mm.size(); ++i)
    model.surface_sample_mm.col(static_cast<Eigen::Index>(i)) = model_part.surface_sample_mm[i];
  return model;
}

std::vector<FieldHypothesis> rank_field_starts(const RegistrationPoints& scene,
                                               const PartSearchModel& model,
                                               std::vector<FieldHypothesis> starts,
                                               const PartPoseSearchParameters& parameters,
                                               const TaskRunner& tasks) {
  const RegistrationPoints scoring = spread_subset(scene, parameters.scoring_points);
  if (scoring.size() == 0 || model.field.empty() || starts.empty()) return {};
  // The first stages on a sparser subset still: most starts are far off, and which few
  // hundred are not shows on fewer points.
  const RegistrationPoints sparse = spread_subset(scoring, parameters.start_scoring_points);
  // Against the whole part, in stages: every start as it is, the best after one alignment
  // step, the best of those after a few more.
  run_field_stages(model.field, model.belt, parameters.field_truncation_mm,
                   {{sparse, 0, static_cast<std::size_t>(parameters.field_candidates)},
                    {sparse, 1, static_cast<std::size_t>(parameters.field_aligned)},
                    {scoring, parameters.field_iterations,
                     static_cast<std::size_t>(parameters.refined_hypotheses)}},
                   starts, tasks);
  return starts;
}

std::vector<FieldHypothesis> field_pose_hypotheses(const RegistrationPoints& scene,
                                                   const ModelBase& base,
                                                   const PartSearchModel& model,
                                                   const PartPoseSearchParameters& parameters,
                                                   const TaskRunner& tasks,
                                                   const ViewSizeGate& views) {
  const RegistrationPoints scoring = spread_subset(scene, parameters.scoring_points);
  if (scoring.size() == 0 || model.field.empty()) return {};
  return rank_field_starts(
      scene, model, turned_view_starts(scoring, base, model, parameters.in_plane_turns, views),
      parameters, tasks);
}

std::vector<ViewPoseHypothesis> register_field_hypotheses(
    const RegistrationPoints& scene, const ModelBase& base, const PartSearchModel& model,
    const std::vector<FieldHypothesis>& hypotheses, const RegistrationParameters& registration,
    const PartPoseSearchParameters& parameters, ModelSurfaces& surfaces, const TaskRunner& tasks) {
  std::vector<ViewPoseHypothesis> best;
  const RegistrationPoints scoring = spread_subset(scene, parameters.scoring_points);
  const PartDistanceField& field = model.field;
  if (scoring.size() == 0 || field.empty()) return best;
  // Each pose onto the part's view nearest to its viewing direction, registered there
  // (ch. 6) on the subset, and ranked against the whole part again. The gate and the
  // registrations run in shares on `tasks`, each hypothesis into its own slot; the views are
  // unpacked in between, in the hypotheses' order, on this thread.
  RegistrationParameters short_registration = registration;
  short_registration.max_iterations = parameters.refinement_iterations;
  const int count = static_cast<int>(hypotheses.size());
  std::vector<std::uint8_t> passes(hypotheses.size());
  run_in_shares(tasks, count, share_count(tasks, count, 1), [&](int, int begin, int end) {
    for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k)
      passes[k] = parameters.refinement_gate.passes(scoring, field, hypotheses[k].T_part_scene);
  });
  std::vector<std::size_t> refined_hypotheses;
  std::vector<int> views;
  for (std::size_t k = 0; k < hypotheses.size(); ++k)
    if (passes[k]) {
      refined_hypotheses.push_back(k);
      views.push_back(nearest_view(base, model, hypotheses[k].T_part_scene));
    }
  std::vector<const RegistrationPoints*> view_points;
  const bool together = std::set<int>(views.begin(), views.end()).size() <=
                        static_cast<std::size_t>(surfaces.capacity());
  if (together) view_points = surfaces.points_of(views);
  best.resize(refined_hypotheses.size());
  const auto refine = [&](std::size_t r) {
    const FieldHypothesis& hypothesis = hypotheses[refined_hypotheses[r]];
    const ModelBaseView& model_view = base.views[static_cast<std::size_t>(views[r])];
    const RigidTransform T_model_scene = model_view.T_scanner_part * hypothesis.T_part_scene;
    const RegistrationResult refined = register_views(
        scoring, together ? *view_points[r] : surfaces.points(views[r]), T_model_scene,
        short_registration, one_after_another(),
        {model.belt.hull_vertices_part_mm, model_view.T_scanner_part, model.belt.weight});
    const RigidTransform& T =
        refined.status == RegistrationStatus::kInvalidInput ? T_model_scene : refined.T_model_scene;
    best[r] = {
        views[r], T,
        field_truncated_mean_square_mm2(scoring, field, model_view.T_scanner_part.inverse() * T,
                                        parameters.field_truncation_mm)};
  };
  const int refined_count = static_cast<int>(refined_hypotheses.size());
  run_in_shares(tasks, refined_count, together ? share_count(tasks, refined_count, 1) : 1,
                [&](int, int begin, int end) {
                  for (int r = begin; r < end; ++r) refine(static_cast<std::size_t>(r));
                });
  std::stable_sort(best.begin(), best.end(),
                   [](const ViewPoseHypothesis& a, const ViewPoseHypothesis& b) {
                     return a.truncated_mean_square_mm2 < b.truncated_mean_square_mm2;
                   });
  return distinct_hypotheses(base, best, parameters, parameters.best_hypotheses);
}

std::vector<ViewPoseHypothesis> search_part_pose(const RegistrationPoints& scene,
                                                 const ModelBase& base,
                                                 const PartSearchModel& model,
                                                 const RegistrationParameters& registration,
                                                 const PartPoseSearchParameters& parameters,
                                                 ModelSurfaces& surfaces) {
  return register_field_hypotheses(scene, base, model,
                                   field_pose_hypotheses(scene, base, model, parameters),
                                   registration, parameters, surfaces);
}

std::vector<ViewPoseHypothesis> align_view_starts_in_field(
    const RegistrationPoints& scene, const ModelBase& base, int view,
    const std::vector<RigidTransform>& starts, const PartSearchModel& model,
    const FieldAlignedStartParameters& parameters, const PartPoseSearchParameters& search,
    int count) {
  std::vector<ViewPoseHypothesis> best;
  const RegistrationPoints scoring = spread_subset(scene, parameters.scoring_points);
  if (scoring.size() == 0 || model.field.empty() || starts.empty()) return best;
  const ModelBaseView& start_view = base.views[static_cast<std::size_t>(view)];
  const RigidTransform T_part_view = start_view.T_scanner_part.inverse();
  std::vector<FieldHypothesis> hypotheses;
  for (const RigidTransform& T_model_scene : starts)
    hypotheses.push_back({T_part_view * T_model_scene, 0.0});
  run_field_stages(model.field, model.belt, parameters.field_truncation_mm,
                   {{scoring, 0, static_cast<std::size_t>(parameters.aligned_starts)},
                    {scoring, parameters.field_iterations, kKeepAll}},
                   hypotheses, one_after_another());
  for (const FieldHypothesis& hypothesis : hypotheses) {
    const int nearest = nearest_view(base, model, hypothesis.T_part_scene);
    best.push_back(
        {nearest,
         base.views[static_cast<std::size_t>(nearest)].T_scanner_part * hypothesis.T_part_scene,
         hypothesis.truncated_mean_square_mm2});
  }
  return distinct_hypotheses(base, best, search, count);
}

QuickFitPoints quick_fit_points(const RegistrationPoints& scene,
                                const CatalogRankParameters& parameters) {
  const std::vector<int> scoring = farthest_point_indices(scene, parameters.start_points);
  std::vector<int> aligning = spread_indices(scene.size(), parameters.aligned_points);
  aligning.insert(aligning.end(), scoring.begin(), scoring.end());
  std::sort(aligning.begin(), aligning.end());
  aligning.erase(std::unique(aligning.begin(), aligning.end()), aligning.end());
  return {select_points(scene, aligning), select_points(scene, scoring)};
}

std::vector<FieldHypothesis> quick_field_poses(const QuickFitPoints& scene, const ModelBase& base,
                                               const PartSearchModel& model,
                                               const PartPoseSearchParameters& search,
                                               const CatalogRankParameters& parameters,
                                               const ViewSizeGate& views) {
  if (scene.aligning.size() == 0 || model.field.empty()) return {};
  std::vector<FieldHypothesis> starts =
      turned_view_starts(scene.aligning, base, model, search.in_plane_turns, views);
  if (starts.empty()) return {};
  run_field_stages(model.field, model.belt, search.field_truncation_mm,
                   {{scene.scoring, 0, static_cast<std::size_t>(parameters.aligned)},
                    {scene.aligning, parameters.iterations, kKeepAll}},
                   starts, one_after_another());
  return starts;
}

}  // namespace cosmos
