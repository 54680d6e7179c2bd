// The confusions of an evaluation (evaluation_confusions.hpp), counted by hand.
#include "sim/evaluation/evaluation_confusions.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cosmos {
namespace {

EvaluationRecord record(int test, const char* truth, int truth_part, const char* predicted,
                        int predicted_part, bool known = true, const char* reason = "") {
  EvaluationRecord r;
  r.test_index = test;
  r.truth_name = truth;
  r.truth_part = truth_part;
  r.truth_in_model_base = known;
  r.predicted_name = predicted;
  r.predicted_part = predicted_part;
  r.rejected = predicted_part < 0;
  r.rejection_reason = reason;
  return r;
}

TEST(EvaluationConfusions, CountsWrongPartsUnknownAcceptedAndRejectionsByPair) {
  const std::vector<EvaluationRecord> records = {
      record(0, "pinion", 1, "pinion", 1),
      record(1, "pinion", 1, "spool", 2),
      record(2, "joint", 3, "anchor", 4),
      record(3, "pinion", 1, "spool", 2),
      record(4, "blade", 5, "", -1, true, "best candidate explains only 55 % of the surface"),
      record(5, "blade", 5, "", -1, true, "best candidate explains only 48 % of the surface"),
      record(6, "hand", 9, "nefertiti", 6, false),
      record(7, "hand", 9, "", -1, false, "whatever"),
  };
  const EvaluationConfusions confusions = count_confusions(records);
  ASSERT_TRUE(confusions.wrong_part_rate.has_value());
  EXPECT_DOUBLE_EQ(*confusions.wrong_part_rate, 3.0 / 6);
  ASSERT_EQ(confusions.wrong_parts.size(), 2u);
  EXPECT_EQ(confusions.wrong_parts[0].truth, "pinion");
  EXPECT_EQ(confusions.wrong_parts[0].other, "spool");
  EXPECT_EQ(confusions.wrong_parts[0].tests, (std::vector<int>{1, 3}));
  EXPECT_EQ(confusions.wrong_parts[1].other, "anchor");
  ASSERT_EQ(confusions.unknown_accepted.size(), 1u);
  EXPECT_EQ(confusions.unknown_accepted[0].other, "nefertiti");
  ASSERT_EQ(confusions.false_rejects.size(), 1u);
  EXPECT_EQ(confusions.false_rejects[0].other, "best candidate explains only # % of the surface");
  EXPECT_EQ(confusions.false_rejects[0].tests, (std::vector<int>{4, 5}));
  const nlohmann::json json = confusions_json(confusions);
  EXPECT_EQ(json["wrong_parts"][0]["tests"], nlohmann::json({1, 3}));
  EXPECT_NE(confusions_text(confusions).find("pinion -> spool: 2"), std::string::npos);
}

TEST(EvaluationConfusions, NoKnownTestsHaveNoRate) {
  EXPECT_FALSE(count_confusions({}).wrong_part_rate.has_value());
  EXPECT_TRUE(confusions_json(count_confusions({}))["wrong_part_rate"].is_null());
}

TEST(EvaluationConfusions, ReasonKindTakesOutNumbers) {
  EXPECT_EQ(reason_kind("explains only 55 % of 1.25 mm."), "explains only # % of # mm.");
  EXPECT_EQ(reason_kind("no digits"), "no digits");
}

}  // namespace
}  // namespace cosmos
