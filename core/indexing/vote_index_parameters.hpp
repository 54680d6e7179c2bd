#pragma once
// The catalog-wide vote index (patch_pair_table.hpp, pose_voting.hpp): its keys and its
// voting, one section of the recognizer's parameters. The table is built from the model
// base's views when the recognizer is made, so none of this is part of the base's key.
#include "core/indexing/patch_pair_key.hpp"
#include "core/indexing/pose_voting.hpp"
#include "core/parameter_visitor.hpp"

namespace cosmos {

struct VoteIndexParameters {
  // Off by default: on the default catalog the voted poses explained a tenth of the scans
  // the selected views did not, and the search over every part in the order of the parts'
  // quick field fits (part_pose_search.hpp) finds those too, for a little more time, while
  // the votes cost as much again on the scans they do not explain.
  bool enabled = false;
  PatchPairKeyParameters key;
  PoseVotingParameters voting;

  template <class Visitor>
  void visit(Visitor& v) {
    v("enabled", enabled, "vote for (part, pose) before searching every part");
    v("key", key, "the key of a pair of CSMPs (§3.2, §5.3)");
    v("voting", voting, "votes for (part, pose) and their modes");
  }
};

}  // namespace cosmos
