// Votes for (part, pose) across the catalog (pose_voting.hpp): a scene showing one of two
// made-up parts in a random pose votes for that part first, in that pose, whichever of the
// part's views the base holds; a scene of a part the base lacks gathers no agreeing votes.
#include "core/indexing/pose_voting.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/rigid_transform.hpp"
#include "tests/core/indexing/patch_object.hpp"

namespace cosmos {
namespace {

RigidTransform random_pose(std::mt19937_64& random) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> offset(-50.0, 50.0);
  const Eigen::Quaterniond q(normal(random), normal(random), normal(random), normal(random));
  return {q.normalized().toRotationMatrix(),
          Eigen::Vector3d(offset(random), offset(random), 250.0 + offset(random))};
}

class PoseVoting : public ::testing::Test {
 protected:
  PoseVoting() {
    base_.parts.resize(2);
    std::mt19937_64 random(5);
    for (int v = 0; v < 3; ++v) {
      base_.views.push_back(
          testing::object_model_view(testing::block_patches(), 0, random_pose(random)));
      base_.views.push_back(
          testing::object_model_view(testing::round_patches(), 1, random_pose(random)));
    }
    table_ = PatchPairTable(base_, PatchPairKeyParameters{});
  }

  ModelBase base_;
  PatchPairTable table_;
};

TEST_F(PoseVoting, TheScenesPartWinsInItsTruePose) {
  PoseVoter voter(table_, PoseVotingParameters{});
  std::mt19937_64 random(11);
  for (int trial = 0; trial < 20; ++trial) {
    const int part = trial % 2;
    const RigidTransform T_scene_part = random_pose(random);
    const CosmosView scene = testing::object_view(
        part == 0 ? testing::block_patches() : testing::round_patches(), T_scene_part);
    const std::span<const VotedPose> voted = voter.vote(scene);
    ASSERT_FALSE(voted.empty());
    EXPECT_EQ(voted.front().part, part) << "trial " << trial;
    const RigidTransform T_part_scene = T_scene_part.inverse();
    EXPECT_LT(
        rotation_angle_between_rad(voted.front().T_part_scene.rotation, T_part_scene.rotation),
        1e-3)
        << "trial " << trial;
    EXPECT_LT((voted.front().T_part_scene.translation_mm - T_part_scene.translation_mm).norm(),
              0.05)
        << "trial " << trial;
    // Every pair of the scene's own part agrees: 2 x 8 or 2 x 5 hits per view around the mode,
    // each weighing at most 1.
    EXPECT_GT(voted.front().votes, 2.0);
  }
}

TEST_F(PoseVoting, IsDeterministicAndBestFirst) {
  PoseVoter voter(table_, PoseVotingParameters{});
  std::mt19937_64 random(3);
  const CosmosView scene = testing::object_view(testing::block_patches(), random_pose(random));
  const std::span<const VotedPose> voted = voter.vote(scene);
  const std::vector<VotedPose> first(voted.begin(), voted.end());
  const std::span<const VotedPose> again = voter.vote(scene);
  ASSERT_EQ(first.size(), again.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].part, again[i].part);
    EXPECT_EQ(first[i].votes, again[i].votes);
    EXPECT_EQ(first[i].T_part_scene.rotation, again[i].T_part_scene.rotation);
    if (i > 0) {
      EXPECT_GE(first[i - 1].votes, first[i].votes);
    }
  }
  EXPECT_LE(first.size(), static_cast<std::size_t>(PoseVotingParameters{}.voted_poses));
}

TEST_F(PoseVoting, AScenePairsWithoutKeysInTheTableVoteForNothing) {
  PoseVoter voter(table_, PoseVotingParameters{});
  // Two saddles 100 mm apart at right angles: no model pair has that key.
  const std::vector<testing::ObjectPatch> unknown = {
      {-0.3, false, {0, 0, 1}, {0, 0, 0}, 400, {1}},
      {-0.3, false, {1, 0, 0}, {100, 0, 0}, 400, {0}}};
  EXPECT_TRUE(voter.vote(testing::object_view(unknown, RigidTransform::identity())).empty());
  EXPECT_EQ(voter.hits(), 0u);
}

}  // namespace
}  // namespace cosmos
