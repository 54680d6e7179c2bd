// Which completed blobs are recognized together: a small piece with a soft successor starts a
// group, the blobs linked to any of its pieces join it, it stays open while a piece's
// successor may still come, and the blobs from an open group on wait for a part still open.
#include "realtime/cell/blob_groups.hpp"

#include <gtest/gtest.h>

#include <deque>

namespace cosmos {
namespace {

constexpr double kSmallPiecePixels = 500;

BlobLinks blob(std::int64_t id, std::int64_t pixels, std::int64_t soft_link_of,
               bool has_soft_successor, std::int64_t completed_profile) {
  BlobLinks links;
  links.part_id = id;
  links.pixels = pixels;
  links.soft_link_of = soft_link_of;
  links.has_soft_successor = has_soft_successor;
  links.completed_profile = completed_profile;
  return links;
}

// Completes blob `index` as the loop would hand it to the recognizer.
void complete(BlobGroups& groups, std::deque<int>& completed, int index, const BlobLinks& links) {
  completed.push_back(index);
  groups.add_completed(index, links, completed);
}

TEST(BlobGroups, ASmallPieceAndTheBlobsLinkedToItAreOneGroup) {
  BlobGroups groups(8, kSmallPiecePixels);
  std::deque<int> completed;
  complete(groups, completed, 3, blob(100, 120, -1, true, 1075));
  EXPECT_EQ(groups.first_of(3), 3);
  EXPECT_TRUE(groups.open(3));
  // The body behind continues it, and a second piece continues the first one too (branches).
  complete(groups, completed, 5, blob(101, 9000, 100, false, 1300));
  complete(groups, completed, 6, blob(102, 300, 100, false, 1310));
  EXPECT_EQ(groups.first_of(5), 3);
  EXPECT_EQ(groups.first_of(6), 3);
  EXPECT_EQ(groups.pieces(3), (std::vector<int>{3, 5, 6}));
  // A later blob linked to nothing in it stays alone.
  complete(groups, completed, 1, blob(103, 9000, 77, false, 1500));
  EXPECT_EQ(groups.first_of(1), -1);
}

TEST(BlobGroups, LargeNeighboursAreNotGrouped) {
  BlobGroups groups(8, kSmallPiecePixels);
  std::deque<int> completed;
  complete(groups, completed, 0, blob(100, 8000, -1, true, 1075));
  complete(groups, completed, 1, blob(101, 9000, 100, false, 1300));
  EXPECT_EQ(groups.first_of(0), -1);
  EXPECT_EQ(groups.first_of(1), -1);
  // Nor does a truncated piece start one: its rows beyond the builder's are not there.
  BlobLinks truncated = blob(102, 100, -1, true, 1400);
  truncated.truncated = true;
  complete(groups, completed, 2, truncated);
  EXPECT_EQ(groups.first_of(2), -1);
}

TEST(BlobGroups, AGroupStaysOpenUntilEveryPartThatStartedByItsPiecesCompletionHasCompleted) {
  BlobGroups groups(8, kSmallPiecePixels);
  std::deque<int> completed;
  complete(groups, completed, 2, blob(100, 120, -1, true, 1075));
  // Its successor started at the row it completed at (1075) and is still open.
  groups.close_if_settled(2, 1075);
  EXPECT_TRUE(groups.open(2));
  complete(groups, completed, 4, blob(101, 9000, 100, false, 1300));
  groups.close_if_settled(2, 1200);  // a part that started before 1075 might still link on
  EXPECT_FALSE(groups.open(2));
  // Closed, it takes no more pieces.
  complete(groups, completed, 5, blob(102, 100, 101, false, 1400));
  EXPECT_EQ(groups.first_of(5), -1);
}

TEST(BlobGroups, AGroupWhosePiecesSuccessorIsGoneCloses) {
  BlobGroups groups(8, kSmallPiecePixels);
  std::deque<int> completed;
  complete(groups, completed, 2, blob(100, 120, -1, true, 1075));
  // The successor merged into another part: nothing joins, and once every part that started
  // by 1075 has completed the group is closed with its one piece.
  groups.close_if_settled(2, 1076);
  EXPECT_FALSE(groups.open(2));
  EXPECT_EQ(groups.pieces(2), (std::vector<int>{2}));
}

TEST(BlobGroups, TheBlobsFromAnOpenGroupOnWaitForAPartStillOpen) {
  BlobGroups groups(8, kSmallPiecePixels);
  std::deque<int> completed;
  complete(groups, completed, 0, blob(99, 9000, -1, false, 900));
  complete(groups, completed, 2, blob(100, 120, -1, true, 1075));
  complete(groups, completed, 6, blob(104, 9000, -1, false, 1090));  // beside the successor
  EXPECT_EQ(groups.waiting_on_open_parts(completed), 2);
  groups.close_if_settled(2, 1200);
  EXPECT_EQ(groups.waiting_on_open_parts(completed), 0);
  // Published, a blob leaves its group.
  groups.leave(2);
  EXPECT_EQ(groups.first_of(2), -1);
}

TEST(BlobLinks, AMergedIdIsOwned) {
  BlobLinks links = blob(100, 10, -1, false, 0);
  links.merged_ids[0] = 140;
  links.merged_count = 1;
  EXPECT_TRUE(links.owns(100));
  EXPECT_TRUE(links.owns(140));
  EXPECT_FALSE(links.owns(141));
}

}  // namespace
}  // namespace cosmos
