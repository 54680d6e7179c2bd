#pragma once
// COSMOS-based view verification (§5.3): the patch-group graph matching of a scene view
// against a model view, returning a feasible correspondence (a set of MappedPairs covering
// both views, whose patch-group graphs are isomorphic, §5.3.1) and its goodness (§5.3.3).
//
// `match` (§5.3.2) starts from the trivial correspondence (all scene patches <-> all model
// patches, always feasible) and repeatedly applies `refine` to its MappedPairs, largest
// first, until none refines further. `refine` splits both sides of a pair: on the scene side
// around the largest patch lp, grown to connected groups of adjacent patches up to
// group_size_limit ({lp}, {lp, lp2}, ...); on the model side around every connected group
// of up to group_size_limit patches. Each choice splits a side into the chosen group and the
// connected components of the rest; when both sides give as many components, every
// one-to-one assignment of components is tried and kept only if it is feasible: each
// (strong) adjacency between the new groups, and between a new group and the groups of the
// other MappedPairs, exists on the other side too (the whole correspondence stays
// isomorphic at all times, §5.3.4), and planar patches meet only planar ones.
//
// As in §5.3.2, a pair is replaced by its best split whenever a feasible one exists, even
// if that split scores lower: the coarseness factor of the goodness (see
// correspondence_goodness.hpp) already makes a feasible split of a coarse pair score higher
// in practice (on every view pair in the tests, keeping a pair unless its split scores at
// least as well changed nothing), and feasibility alone decides how fine the result gets.
//
// Budgets are counts, never times (§5.3.2 "until some maximum number of correspondences
// checked"): one operation is one pairing of a scene split with a model split, or one
// complete assignment of components scored. Every loop runs in index order and ties keep
// the first candidate found (smaller groups first, then lower patch indices), so the same
// views always give the same correspondence.
#include <cstdint>
#include <vector>

#include "core/matching/correspondence_goodness.hpp"
#include "core/parameter_visitor.hpp"
#include "core/representation/cosmos_view.hpp"

namespace cosmos {

struct PatchGroupMatchParameters {
  int group_size_limit = 3;              // §5.3.2 "groupsize limit": patches grown around lp or rp
  std::int64_t max_operations = 200000;  // the whole match
  std::int64_t max_operations_per_refine = 20000;  // one call of refine
  // Shared boundary, as a fraction of the smaller patch's perimeter, below which an
  // adjacency is weak and need not be matched (§5.4.3); 0: every adjacency must match.
  double min_adjacency_strength = 0.05;
  GoodnessParameters goodness;

  template <class Visitor>
  void visit(Visitor& v) {
    v("group_size_limit", group_size_limit, "patches grown around lp or rp (§5.3.2)", Range{1, 64});
    v("max_operations", max_operations, "operations of the whole match", Range{1, 1e12});
    v("max_operations_per_refine", max_operations_per_refine, "operations of one refine",
      Range{1, 1e12});
    v("min_adjacency_strength", min_adjacency_strength,
      "weaker adjacencies need not match (§5.4.3), of the smaller perimeter", Range{0, 1});
    v("goodness", goodness, "correspondence goodness (§5.3.3)");
  }
};

enum class PatchGroupMatchStatus {
  kOk,
  kEmptyView,        // a view without patches: the trivial correspondence, score 0
  kTooManyPatches,   // over kMaxGraphPatches: the trivial correspondence, score 0
  kBudgetExhausted,  // max_operations reached: the (feasible) correspondence so far
};

struct MappedPair {
  std::vector<int> scene_patches;  // Csmp ids, ascending
  std::vector<int> model_patches;
  PairGoodness goodness;
};

struct PatchGroupMatch {
  PatchGroupMatchStatus status = PatchGroupMatchStatus::kOk;
  std::vector<MappedPair> pairs;  // ordered by their lowest scene patch index
  double score = 0;               // §5.3.3 quality with the coarseness factor, in [0, 1]
  double fineness = 0;  // area-weighted mean of the pairs' fineness: 1 = all single patches
  std::int64_t operations = 0;
  int refinements = 0;  // MappedPairs replaced by finer ones
};

PatchGroupMatch match_patch_groups(const CosmosView& scene, const CosmosView& model,
                                   const PatchGroupMatchParameters& parameters = {});

}  // namespace cosmos
