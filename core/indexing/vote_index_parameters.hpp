#pragma once
// The catalog-wide vote index (patch_pair_table.hpp, pose_voting.hpp): its keys and its
// voting, one section of the recognizer's parameters. The table is built from the model
// base's views when the recognizer is made, so none of this is part of the base's key.
#include "core/indexing/patch_pair_key.hpp"
#include "core/indexing/pose_voting.hpp"
#include "core/parameter_visitor.hpp"

namespace cosmos {

struct VoteIndexParameters {
  bool enabled = true;  // false: the recognizer falls back to the pose search over every part
  PatchPairKeyParameters key;
  PoseVotingParameters voting;
  // The first voted parts (in vote order) are searched over all their views
  // (part_pose_search.hpp) before the search over every part.
  int searched_parts = 3;

  template <class Visitor>
  void visit(Visitor& v) {
    v("enabled", enabled, "vote for (part, pose) before searching every part");
    v("key", key, "the key of a pair of CSMPs (§3.2, §5.3)");
    v("voting", voting, "votes for (part, pose) and their modes");
    v("searched_parts", searched_parts, "voted parts searched before every part", Range{0, 100000});
  }
};

}  // namespace cosmos
