// Held pieces: shadow pieces (softly linked blobs with nothing recognized in them) wait for
// the part they may belong to, a few blobs at most and no longer than a blob that can join
// them may still come; nearby shadow pieces that are not recognized, alone
// or together, are one part and are reported once, by the first of them. Three of them held
// together is the case where releasing the first erases the other two from the held list
// while the first is still being released.
#include "realtime/cell/piece_joiner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/loop/part_rows.hpp"
#include "realtime/loop/row_block_pool.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

constexpr double kGridMm = 0.4;
constexpr int kImageSide = 6;  // far too few pixels for any part: the recognizer rejects it

class PieceJoinerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    base_ = std::make_unique<ModelBase>(read_model_base(testing::regression_model_base()));
    recognizer_ = std::make_unique<Recognizer>(*base_, CosmosParameters{}, RecognitionParameters{});
  }
  static void TearDownTestSuite() {
    recognizer_.reset();
    base_.reset();
  }

  PieceJoinerTest() : pool_(8, PartRows::record_bytes(kImageSide)) {
    context_.recognizer = recognizer_.get();
    context_.model_base = base_.get();
    context_.grid_mm = kGridMm;
  }

  // A blob of `rows` profiles from `first_profile` with nothing recognized in it: one
  // rejection numbered `part_seq`, a small flat surface, softly linked to the piece before
  // it and to the one after it.
  std::vector<JoinedRecognition> add_shadow_piece(PieceJoiner& joiner, std::int64_t first_profile,
                                                  std::int64_t part_seq) {
    PartBuilder builder(CosmosParameters{}, kImageSide, kImageSide, kGridMm, pool_);
    builder.first_profile = first_profile;
    builder.rows_added = kImageSide;
    builder.soft_link_of = part_seq - 1;
    builder.has_soft_successor = true;
    BlobRecognition blob;
    PartRecognition rejection;
    rejection.pose.status = PoseStatus::kRejected;
    rejection.pose.part_seq = part_seq;
    rejection.pose.reason = "piece " + std::to_string(part_seq);
    rejection.first_profile = first_profile;
    rejection.last_profile = first_profile + kImageSide - 1;
    blob.parts.push_back(std::move(rejection));
    blob.image = RangeImage(kImageSide, kImageSide, kGridMm, kGridMm);
    blob.image.origin_y_mm = static_cast<double>(first_profile) * kGridMm;
    for (int row = 0; row < kImageSide; ++row)
      for (int column = 0; column < kImageSide; ++column) {
        blob.image.z_mm(column, row) = 3.0F;
        blob.points_loop_mm.emplace_back(column * kGridMm, blob.image.y_mm(row), 3.0);
      }
    return joiner.add(std::move(blob), builder);
  }

  std::vector<JoinedRecognition> add_recognized_blob(PieceJoiner& joiner,
                                                     std::int64_t first_profile,
                                                     std::int64_t part_seq, double past_last_row_mm,
                                                     double rms_mm = 0);

  // A blob with nothing in it: the held pieces wait one blob more.
  std::vector<JoinedRecognition> add_empty_blob(PieceJoiner& joiner) {
    PartBuilder builder(CosmosParameters{}, kImageSide, kImageSide, kGridMm, pool_);
    return joiner.add(BlobRecognition{}, builder);
  }

  static std::unique_ptr<ModelBase> base_;
  static std::unique_ptr<Recognizer> recognizer_;
  RowBlockPool pool_;
  PartRecognitionContext context_;
};

std::unique_ptr<ModelBase> PieceJoinerTest::base_;
std::unique_ptr<Recognizer> PieceJoinerTest::recognizer_;

TEST_F(PieceJoinerTest, ThreeNearbyShadowPiecesAreReportedOnceByTheFirst) {
  PieceJoiner joiner(context_);
  EXPECT_TRUE(add_shadow_piece(joiner, 100, 1).empty());
  EXPECT_TRUE(add_shadow_piece(joiner, 140, 2).empty());
  EXPECT_TRUE(add_shadow_piece(joiner, 180, 3).empty());
  // The first piece has waited three blobs after its own; the fourth releases it.
  EXPECT_TRUE(add_empty_blob(joiner).empty());
  const std::vector<JoinedRecognition> released = add_empty_blob(joiner);
  ASSERT_EQ(released.size(), 1U);
  EXPECT_EQ(released[0].recognition.pose.part_seq, 1);
  EXPECT_EQ(released[0].recognition.pose.reason, "piece 1");
  EXPECT_EQ(released[0].recognition.pose.status, PoseStatus::kRejected);
  EXPECT_TRUE(joiner.finish().empty());
}

TEST_F(PieceJoinerTest, AShadowPieceFarFromTheOthersIsReportedOnItsOwn) {
  PieceJoiner joiner(context_);
  EXPECT_TRUE(add_shadow_piece(joiner, 100, 1).empty());
  EXPECT_TRUE(add_shadow_piece(joiner, 140, 2).empty());
  EXPECT_TRUE(add_shadow_piece(joiner, 180, 3).empty());
  EXPECT_TRUE(add_shadow_piece(joiner, 5000, 4).empty());
  const std::vector<JoinedRecognition> released = add_empty_blob(joiner);
  ASSERT_EQ(released.size(), 1U);
  EXPECT_EQ(released[0].recognition.pose.part_seq, 1);
  const std::vector<JoinedRecognition> rest = joiner.finish();
  ASSERT_EQ(rest.size(), 1U);
  EXPECT_EQ(rest[0].recognition.pose.part_seq, 4);
}

TEST_F(PieceJoinerTest, APieceGoesOutOnceNoBlobStillToComeCanJoinIt) {
  PieceJoiner joiner(context_);
  EXPECT_TRUE(add_shadow_piece(joiner, 100, 1).empty());  // profiles 100-105
  // A blob may still start within the joiner's reach (100 profiles) after its last profile.
  EXPECT_TRUE(joiner.release_settled(150).empty());
  EXPECT_TRUE(joiner.release_settled(205).empty());
  const std::vector<JoinedRecognition> released = joiner.release_settled(206);
  ASSERT_EQ(released.size(), 1U);
  EXPECT_EQ(released[0].recognition.pose.part_seq, 1);
  EXPECT_TRUE(joiner.finish().empty());
}

TEST_F(PieceJoinerTest, SettledShadowPiecesNearEachOtherAreReportedOnce) {
  PieceJoiner joiner(context_);
  EXPECT_TRUE(add_shadow_piece(joiner, 100, 1).empty());
  EXPECT_TRUE(add_shadow_piece(joiner, 140, 2).empty());
  EXPECT_TRUE(add_shadow_piece(joiner, 5000, 3).empty());
  const std::vector<JoinedRecognition> released = joiner.release_settled(1000);
  ASSERT_EQ(released.size(), 1U);
  EXPECT_EQ(released[0].recognition.pose.part_seq, 1);
  const std::vector<JoinedRecognition> rest = joiner.finish();
  ASSERT_EQ(rest.size(), 1U);
  EXPECT_EQ(rest[0].recognition.pose.part_seq, 3);
}

// A blob of kImageSide profiles from `first_profile` in which part 0 was recognized, softly
// linked to the part behind it, placed so that its hull's far end (along the belt) lies
// `past_last_row_mm` beyond the blob's last row, registered with residual `rms_mm`.
std::vector<JoinedRecognition> PieceJoinerTest::add_recognized_blob(PieceJoiner& joiner,
                                                                    std::int64_t first_profile,
                                                                    std::int64_t part_seq,
                                                                    double past_last_row_mm,
                                                                    double rms_mm) {
  PartBuilder builder(CosmosParameters{}, kImageSide, kImageSide, kGridMm, pool_);
  builder.first_profile = first_profile;
  builder.rows_added = kImageSide;
  builder.has_soft_successor = true;
  const std::int64_t last_profile = first_profile + kImageSide - 1;
  double far_y_mm = -1e9;
  for (const Eigen::Vector3d& corner : base_->parts[0].hull_vertices_mm)
    far_y_mm = std::max(far_y_mm, corner.y());
  BlobRecognition blob;
  PartRecognition part;
  part.pose.status = PoseStatus::kOk;
  part.pose.part_seq = part_seq;
  part.result.part = 0;
  part.result.T_scanner_part.translation_mm.y() =
      static_cast<double>(last_profile) * kGridMm + past_last_row_mm - far_y_mm;
  part.result.registration_rms_mm = rms_mm;
  part.first_profile = first_profile;
  part.last_profile = last_profile;
  blob.parts.push_back(std::move(part));
  for (int row = 0; row < kImageSide; ++row)
    for (int column = 0; column < kImageSide; ++column)
      blob.points_loop_mm.emplace_back(column * kGridMm, (first_profile + row) * kGridMm, 3.0);
  return joiner.add(std::move(blob), builder);
}

// A blob in which a part was recognized, softly linked to the part behind it, waits for that
// part when its part reaches past the blob's last row (the part behind may be more of it, cut
// off by its shadow) and is counted; a shadow piece with nothing recognized in it waits too
// but is not.
TEST_F(PieceJoinerTest, ARecognizedBlobWaitsForItsSoftSuccessorAndIsCounted) {
  ASSERT_FALSE(base_->parts[0].hull_vertices_mm.empty());
  PieceJoiner joiner(context_);
  EXPECT_TRUE(add_shadow_piece(joiner, 100, 1).empty());
  EXPECT_EQ(joiner.blobs_held_for_successor(), 0);
  EXPECT_TRUE(add_recognized_blob(joiner, 2000, 2, 5.0).empty());
  EXPECT_EQ(joiner.blobs_held_for_successor(), 1);
  // It goes out once no blob still to come can join it: with its part's pose.
  const std::vector<JoinedRecognition> released = joiner.release_settled(2000 + 1000);
  ASSERT_EQ(released.size(), 2U);
  EXPECT_EQ(released[0].recognition.pose.part_seq, 1);
  EXPECT_EQ(released[1].recognition.pose.part_seq, 2);
  EXPECT_EQ(released[1].recognition.pose.status, PoseStatus::kOk);
  EXPECT_TRUE(joiner.finish().empty());
}

// A part clearly recognized that ends in its own blob (its far end within a pose's error of
// the last row) is not continued behind the shadow: its pose goes out at once, uncounted; a
// millimetre and a half further and it waits, as does one that ends in its blob but nearly
// failed recognition (a residual near max_rms_mm: maybe a piece of the part behind).
TEST_F(PieceJoinerTest, ARecognizedPartEndingInItsBlobDoesNotWaitForTheSuccessor) {
  PieceJoiner joiner(context_);
  const std::vector<JoinedRecognition> out = add_recognized_blob(joiner, 2000, 1, 0.5);
  ASSERT_EQ(out.size(), 1U);
  EXPECT_EQ(out[0].recognition.pose.part_seq, 1);
  EXPECT_EQ(out[0].recognition.pose.status, PoseStatus::kOk);
  EXPECT_EQ(joiner.blobs_held_for_successor(), 0);
  EXPECT_FALSE(joiner.holding());
  EXPECT_TRUE(add_recognized_blob(joiner, 4000, 2, 1.5).empty());
  EXPECT_EQ(joiner.blobs_held_for_successor(), 1);
  EXPECT_TRUE(joiner.holding());
  const double max_rms_mm = recognizer_->parameters().max_rms_mm;
  EXPECT_EQ(add_recognized_blob(joiner, 8000, 3, 0.5, 0.4 * max_rms_mm).size(), 1U);
  EXPECT_EQ(joiner.blobs_held_for_successor(), 1);
  EXPECT_TRUE(add_recognized_blob(joiner, 12000, 4, 0.5, 0.9 * max_rms_mm).empty());
  EXPECT_EQ(joiner.blobs_held_for_successor(), 2);
}

TEST_F(PieceJoinerTest, PiecesWaitingTheirBlobsAreHeldTillTheEnd) {
  PieceJoiner joiner(context_);
  EXPECT_TRUE(add_shadow_piece(joiner, 100, 1).empty());
  EXPECT_TRUE(add_shadow_piece(joiner, 140, 2).empty());
  const std::vector<JoinedRecognition> rest = joiner.finish();
  ASSERT_EQ(rest.size(), 1U);
  EXPECT_EQ(rest[0].recognition.pose.part_seq, 1);
}

}  // namespace
}  // namespace cosmos
