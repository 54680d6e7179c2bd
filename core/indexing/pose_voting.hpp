#pragma once
// Votes of the scene's CSMP pairs for (part, pose) across the whole catalog: each
// scene pair looks up its key and the neighbouring bins' (patch_pair_key.hpp) in the table
// (patch_pair_table.hpp), and every model pair found there implies the pose of the scene in
// that part's frame, T_part_scene = T_part_pair(model) * T_scene_pair⁻¹. The pairs of the
// scene's true part agree on one pose; chance matches scatter. Votes of one part are
// clustered in pose space (a rotation within same_pose_deg and the scene's centre within
// same_pose_mm): the hit with the most weight around it is a mode, its neighbours' mean the
// pose, and they are then taken out before the next mode is sought. The recognizer registers
// only the strongest modes (recognizer.hpp), instead of searching every part.
//
// A key shared by many model pairs (the right angle between two flat faces, on every
// mechanical part) says little about which part this is: each hit of a scene pair weighs
// 1 / sqrt(the entries its keys hold), and a pair whose keys hold more than
// max_entries_per_pair votes with an even sample of them. Everything is counted: the voter's
// buffers are sized once, at construction, and a scene with more pair hits than max_hits
// stops adding at that many (in scene patch order), so the result depends only on the input.
#include <cstddef>
#include <span>
#include <vector>

#include "core/indexing/patch_pair_table.hpp"
#include "core/parameter_visitor.hpp"
#include "core/representation/cosmos_view.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

struct PoseVotingParameters {
  int max_entries_per_pair = 1000;
  int max_hits = 60000;
  int max_hits_per_part = 400;  // the heaviest of a part's hits are clustered
  double same_pose_deg = 20.0;
  double same_pose_mm = 15.0;
  int poses_per_part = 2;
  int voted_poses = 8;  // returned, best first

  template <class Visitor>
  void visit(Visitor& v) {
    v("max_entries_per_pair", max_entries_per_pair,
      "a scene pair whose keys hold more votes with an even sample", Range{1, 100000000});
    v("max_hits", max_hits, "pair hits one scene collects, at most", Range{1, 100000000});
    v("max_hits_per_part", max_hits_per_part, "a part's heaviest hits are clustered",
      Range{1, 100000});
    v("same_pose_deg", same_pose_deg, "votes whose rotations differ less fall together, deg",
      Range::above(0, 180));
    v("same_pose_mm", same_pose_mm, "and whose scene centres lie closer, mm", Range::above(0, 1e4));
    v("poses_per_part", poses_per_part, "modes taken per part", Range{1, 1000});
    v("voted_poses", voted_poses, "modes returned, best first", Range{0, 100000});
  }
};

struct VotedPose {
  int part = -1;  // index into ModelBase::parts
  RigidTransform T_part_scene;
  double votes = 0;  // the weight of the hits around the mode
};

class PoseVoter {
 public:
  // The table must outlive the voter.
  PoseVoter(const PatchPairTable& table, const PoseVotingParameters& parameters);

  // The strongest modes, best first (ties: lower part index first); valid until the next call.
  std::span<const VotedPose> vote(const CosmosView& scene);
  std::size_t hits() const { return hits_.size(); }

 private:
  struct Hit {
    Eigen::Quaternionf q_part_scene;
    Eigen::Vector3f centre_part_mm;  // the scene's centre in the part frame
    float weight = 0;
    std::int32_t part = 0;
    std::int32_t order = 0;  // arrival, the tie-break that keeps sorting deterministic
  };

  void collect_hits(const CosmosView& scene, const Eigen::Vector3d& centre_scene_mm);
  void find_modes(std::size_t first, std::size_t end, const Eigen::Vector3d& centre_scene_mm);
  bool same_pose(const Hit& a, const Hit& b) const;

  const PatchPairTable& table_;
  PoseVotingParameters parameters_;
  float min_quaternion_dot_ = 1;
  float max_distance2_mm2_ = 0;
  std::vector<Hit> hits_;
  std::vector<float> density_;
  std::vector<char> taken_;
  std::vector<VotedPose> poses_;
};

}  // namespace cosmos
