#include "core/matching/patch_group_matching.hpp"

#include <algorithm>
#include <array>

#include "core/matching/patch_group.hpp"

namespace cosmos {
namespace {

constexpr int kMaxComponents = kMaxSplitComponents;
// Slack on the bounds, so that rounding never prunes a candidate that would tie the best.
constexpr double kScoreTolerance = 1e-12;

// One side of a candidate split (§5.3.2 `split`), with what the feasibility test and the
// goodness need of each component. Splitting is cheap; the rest is filled in by `prepare`
// only for splits that meet a partner with as many components.
struct SideSplit {
  GroupSplit split;
  bool prepared = false;
  std::array<GroupDescriptor, kMaxComponents> descriptors{};
  // Bit p: adjacent to this side's group of pair p of the current correspondence.
  std::array<PatchSet, kMaxComponents> external_any{};
  std::array<PatchSet, kMaxComponents> external_strong{};
  // Bit c: adjacent to component c of the same split.
  std::array<std::uint32_t, kMaxComponents> internal_any{};
  std::array<std::uint32_t, kMaxComponents> internal_strong{};
};

void prepare(SideSplit& side, const PatchGraph& graph, const std::vector<PatchSet>& side_groups,
             std::size_t refined_pair) {
  if (side.prepared) return;
  side.prepared = true;
  for (int c = 0; c < side.split.count; ++c) {
    const PatchSet component = side.split.components[c];
    side.descriptors[c] = describe_group(graph, component);
    const PatchSet ring = adjacent_patches(graph, component);
    PatchSet strong_ring = 0;
    for (PatchSet m = component; m != 0; m &= m - 1) {
      strong_ring |= graph.nodes[lowest_patch(m)].strongly_adjacent;
    }
    strong_ring &= ~component;
    side.external_any[c] = side.external_strong[c] = 0;
    side.internal_any[c] = side.internal_strong[c] = 0;
    for (std::size_t p = 0; p < side_groups.size(); ++p) {
      if (p == refined_pair) continue;
      if ((ring & side_groups[p]) != 0) side.external_any[c] |= PatchSet{1} << p;
      if ((strong_ring & side_groups[p]) != 0) side.external_strong[c] |= PatchSet{1} << p;
    }
    for (int d = 0; d < side.split.count; ++d) {
      if (d == c) continue;
      if ((ring & side.split.components[d]) != 0) side.internal_any[c] |= 1u << d;
      if ((strong_ring & side.split.components[d]) != 0) side.internal_strong[c] |= 1u << d;
    }
  }
}

bool subset_of(PatchSet a, PatchSet b) { return (a & ~b) == 0; }

class Matcher {
 public:
  Matcher(const PatchGraph& scene, const PatchGraph& model,
          const PatchGroupMatchParameters& parameters)
      : scene_(scene), model_(model), parameters_(parameters) {}

  std::vector<GroupPair> run() {
    std::vector<GroupPair> pairs{{scene_.all, model_.all}};
    std::vector<bool> settled{false};
    while (!budget_exhausted()) {
      const int next = next_pair(pairs, settled);
      if (next < 0) break;
      if (refine(pairs, static_cast<std::size_t>(next))) {
        ++refinements_;
        settled.resize(pairs.size(), false);
      } else {
        settled[next] = true;
      }
    }
    return pairs;
  }

  std::int64_t operations() const { return operations_; }
  int refinements() const { return refinements_; }
  bool budget_exhausted() const { return operations_ >= parameters_.max_operations; }

 private:
  // Larger pairs first: they weigh most in the goodness (§5.3.3), and large patches are the
  // ones that correspond reliably (§5.3.2).
  int next_pair(const std::vector<GroupPair>& pairs, const std::vector<bool>& settled) const {
    int best = -1;
    double best_weight = -1;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      if (settled[p] || patch_count(pairs[p].scene) < 2 || patch_count(pairs[p].model) < 2)
        continue;
      const double weight = summarize_group(scene_, pairs[p].scene).area_fraction +
                            summarize_group(model_, pairs[p].model).area_fraction;
      if (weight > best_weight) {
        best_weight = weight;
        best = static_cast<int>(p);
      }
    }
    return best;
  }

  double weighted_score(const GroupDescriptor& scene, const GroupDescriptor& model) const {
    const PairGoodness g = evaluate_pair(scene, model, parameters_.goodness);
    return g.weight * g.score;
  }

  // §5.3.2 `refine`: replaces pairs[index] by its best feasible split, if it has one.
  bool refine(std::vector<GroupPair>& pairs, std::size_t index) {
    const PatchSet left = pairs[index].scene;
    const PatchSet right = pairs[index].model;
    scene_groups_.resize(pairs.size());
    model_groups_.resize(pairs.size());
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      scene_groups_[p] = pairs[p].scene;
      model_groups_[p] = pairs[p].model;
    }
    refine_budget_end_ =
        std::min(parameters_.max_operations, operations_ + parameters_.max_operations_per_refine);
    best_sum_ = 0;
    found_ = false;

    // The buffers outlive the call, so refining allocates nothing once they have grown.
    right_splits_.clear();
    for (PatchSet selected : connected_subsets(model_, right, -1, parameters_.group_size_limit)) {
      SideSplit& side = right_splits_.emplace_back();
      side.split = split_group(model_, right, selected);
      if (side.split.count == 0) right_splits_.pop_back();
    }
    const int lp = largest_patch(scene_, left);
    for (PatchSet selected : connected_subsets(scene_, left, lp, parameters_.group_size_limit)) {
      if (operations_ >= refine_budget_end_) break;
      left_split_.split = split_group(scene_, left, selected);
      left_split_.prepared = false;
      if (left_split_.split.count == 0) continue;
      for (SideSplit& right_split : right_splits_) {
        if (operations_ >= refine_budget_end_) break;
        ++operations_;
        if (right_split.split.count != left_split_.split.count) continue;
        prepare(left_split_, scene_, scene_groups_, index);
        prepare(right_split, model_, model_groups_, index);
        assign(left_split_, right_split);
      }
    }
    if (!found_) return false;

    const int count = best_left_.split.count;
    pairs[index] = {best_left_.split.components[0],
                    best_right_->split.components[best_assignment_[0]]};
    for (int c = 1; c < count; ++c) {
      pairs.push_back(
          {best_left_.split.components[c], best_right_->split.components[best_assignment_[c]]});
    }
    return true;
  }

  // Tries every feasible one-to-one assignment of left components to right components
  // (§5.3.2: "pair every component on the left with every component on the right").
  void assign(const SideSplit& left, const SideSplit& right) {
    const int k = left.split.count;
    if (!may_beat_best(left, right)) return;
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j < k; ++j) {
        // The cheap adjacency tests first: most pairings fail them.
        const bool feasible =
            subset_of(left.external_strong[i], right.external_any[j]) &&
            subset_of(right.external_strong[j], left.external_any[i]) &&
            planar_compatible(left.descriptors[i].group, right.descriptors[j].group);
        score_[i][j] = feasible ? weighted_score(left.descriptors[i], right.descriptors[j]) : -1.0;
      }
      if (std::none_of(score_[i].begin(), score_[i].begin() + k, [](double s) { return s >= 0; })) {
        return;  // a component without any feasible partner: no assignment exists
      }
    }
    // Branch and bound: what the components from i on can add at most, each taking its best
    // partner.
    remaining_[k] = 0;
    for (int i = k - 1; i >= 0; --i) {
      remaining_[i] =
          remaining_[i + 1] + *std::max_element(score_[i].begin(), score_[i].begin() + k);
    }
    std::array<int, kMaxComponents> assignment{};
    search(left, right, 0, 0u, 0.0, assignment);
  }

  // Cheap bound before the goodness terms: a pair's weight times its area goodness is
  // min(a_scene, a_model) (§5.3.3 area form), and the other terms are at most 1.
  bool may_beat_best(const SideSplit& left, const SideSplit& right) const {
    double bound = 0;
    for (int i = 0; i < left.split.count; ++i) {
      const GroupSummary& a = left.descriptors[i].group;
      double best = 0;
      for (int j = 0; j < right.split.count; ++j) {
        const GroupSummary& b = right.descriptors[j].group;
        best = std::max(best, std::min(a.area_fraction, b.area_fraction) *
                                  coarseness_factor(a, b, parameters_.goodness));
      }
      bound += best;
    }
    return can_beat_best(bound);
  }

  // Whether a sub-correspondence whose quality is at most `bound` could beat the best one
  // so far; ties keep the first found.
  bool can_beat_best(double bound) const { return !found_ || bound + kScoreTolerance > best_sum_; }

  void search(const SideSplit& left, const SideSplit& right, int i, std::uint32_t used, double sum,
              std::array<int, kMaxComponents>& assignment) {
    const int k = left.split.count;
    if (!can_beat_best(sum + remaining_[i])) return;
    if (i == k) {
      ++operations_;
      if (!found_ || sum > best_sum_) {
        found_ = true;
        best_sum_ = sum;
        best_left_ = left;
        best_right_ = &right;
        best_assignment_ = assignment;
      }
      return;
    }
    for (int j = 0; j < k; ++j) {
      if (operations_ >= refine_budget_end_) return;
      if ((used >> j) & 1u || score_[i][j] < 0) continue;
      bool consistent = true;
      for (int earlier = 0; earlier < i && consistent; ++earlier) {
        const int partner = assignment[earlier];
        const bool left_strong = (left.internal_strong[i] >> earlier) & 1u;
        const bool left_any = (left.internal_any[i] >> earlier) & 1u;
        const bool right_strong = (right.internal_strong[j] >> partner) & 1u;
        const bool right_any = (right.internal_any[j] >> partner) & 1u;
        consistent = (!left_strong || right_any) && (!right_strong || left_any);
      }
      if (!consistent) continue;
      assignment[i] = j;
      search(left, right, i + 1, used | (1u << j), sum + score_[i][j], assignment);
    }
  }

  const PatchGraph& scene_;
  const PatchGraph& model_;
  const PatchGroupMatchParameters& parameters_;
  std::int64_t operations_ = 0;
  std::int64_t refine_budget_end_ = 0;
  int refinements_ = 0;
  std::array<std::array<double, kMaxComponents>, kMaxComponents> score_{};
  std::array<double, kMaxComponents + 1> remaining_{};
  double best_sum_ = 0;
  bool found_ = false;
  std::vector<PatchSet> scene_groups_;
  std::vector<PatchSet> model_groups_;
  std::vector<SideSplit> right_splits_;
  SideSplit left_split_;
  SideSplit best_left_;
  const SideSplit* best_right_ = nullptr;  // into right_splits_
  std::array<int, kMaxComponents> best_assignment_{};
};

std::vector<int> ids_of(const CosmosView& view, PatchSet group) {
  std::vector<int> ids;
  for (PatchSet g = group; g != 0; g &= g - 1) ids.push_back(view.patches[lowest_patch(g)].id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<int> all_ids(const CosmosView& view) {
  std::vector<int> ids;
  for (const Csmp& patch : view.patches) ids.push_back(patch.id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

}  // namespace

PatchGroupMatch match_patch_groups(const CosmosView& scene, const CosmosView& model,
                                   const PatchGroupMatchParameters& parameters) {
  PatchGroupMatch result;
  const PatchGraph scene_graph = build_patch_graph(scene, parameters.min_adjacency_strength);
  const PatchGraph model_graph = build_patch_graph(model, parameters.min_adjacency_strength);
  const bool empty = scene.patches.empty() || model.patches.empty();
  const bool too_many =
      scene_graph.status != PatchGraphStatus::kOk || model_graph.status != PatchGraphStatus::kOk;
  if (empty || too_many) {
    result.status =
        empty ? PatchGroupMatchStatus::kEmptyView : PatchGroupMatchStatus::kTooManyPatches;
    PairGoodness nothing;
    nothing.area = nothing.shape_index = nothing.curvedness = nothing.neighbor = 0;
    nothing.goodness = nothing.fineness = 0;
    result.pairs.push_back({all_ids(scene), all_ids(model), nothing});
    return result;
  }

  Matcher matcher(scene_graph, model_graph, parameters);
  std::vector<GroupPair> pairs = matcher.run();
  std::sort(pairs.begin(), pairs.end(), [](const GroupPair& a, const GroupPair& b) {
    return lowest_patch(a.scene) < lowest_patch(b.scene);
  });
  for (const GroupPair& pair : pairs) {
    const PairGoodness g =
        evaluate_pair(describe_group(scene_graph, pair.scene),
                      describe_group(model_graph, pair.model), parameters.goodness);
    result.score += g.weight * g.score;
    result.fineness += g.weight * g.fineness;
    result.pairs.push_back({ids_of(scene, pair.scene), ids_of(model, pair.model), g});
  }
  result.score = std::clamp(result.score, 0.0, 1.0);
  result.fineness = std::clamp(result.fineness, 0.0, 1.0);
  result.operations = matcher.operations();
  result.refinements = matcher.refinements();
  if (matcher.budget_exhausted()) result.status = PatchGroupMatchStatus::kBudgetExhausted;
  return result;
}

}  // namespace cosmos
