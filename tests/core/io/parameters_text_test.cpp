// The canonical parameters text (core/io/parameters_text.hpp) a model base records: nested by
// the keys' dots, sorted, and compared key by key so a refusal names the differing key; whole
// parameter structs written and read back through their visit().
#include "core/io/parameters_text.hpp"

#include <gtest/gtest.h>

#include "core/cosmos_parameters.hpp"
#include "core/recognition/recognizer.hpp"
#include "tests/common/parameter_fields.hpp"

namespace cosmos {
namespace {

TEST(ParameterText, IsNestedSortedAndNamesTheFirstDifferingKey) {
  ParameterText text;
  text.set_number("scanner.z_noise_mm", 0.02);
  text.set_integer("cosmos.fit.window_size", 5);
  text.set_flag("cosmos.fit.bicubic", true);
  EXPECT_EQ(text.text(),
            "{\n  \"cosmos\": {\n    \"fit\": {\n      \"bicubic\": true,\n      \"window_size\": "
            "5\n    }\n  },\n"
            "  \"scanner\": {\n    \"z_noise_mm\": 0.02\n  }\n}\n");
  ParameterText other = text;
  EXPECT_FALSE(first_parameter_difference(text.text(), other.text()));
  other.set_number("scanner.z_noise_mm", 0.05);
  other.set_integer("cosmos.fit.window_size", 7);
  const auto difference = first_parameter_difference(text.text(), other.text());
  ASSERT_TRUE(difference);
  EXPECT_EQ(difference->key, "cosmos.fit.window_size");
  EXPECT_EQ(difference->expected, "5");
  EXPECT_EQ(difference->actual, "7");
  ParameterText missing;
  missing.set_integer("cosmos.fit.window_size", 5);
  missing.set_flag("cosmos.fit.bicubic", true);
  const auto absent = first_parameter_difference(text.text(), missing.text());
  ASSERT_TRUE(absent);
  EXPECT_EQ(absent->key, "scanner.z_noise_mm");
  EXPECT_EQ(absent->actual, "(absent)");
}

TEST(ParameterText, TextThatIsNotAnObjectDiffersAtTheTextKey) {
  ParameterText text;
  text.set_integer("views.count", 320);
  const auto difference = first_parameter_difference(text.text(), "views: 320");
  ASSERT_TRUE(difference);
  EXPECT_EQ(difference->key, "(text)");
  EXPECT_FALSE(first_parameter_difference("{}", "{ }"));
}

TEST(ParameterText, WritesEveryVisitedFieldUnderItsPrefix) {
  ParameterText text;
  text.set_parameters("cosmos", CosmosParameters{});
  const auto values = ParameterValues::parse(text.text());
  ASSERT_TRUE(values);
  EXPECT_EQ(values->integer("cosmos.fit.window_size"), 5);
  EXPECT_EQ(values->flag("cosmos.fit.bicubic"), true);
  EXPECT_EQ(values->number("cosmos.smoothing.curvature_floor_per_mm"), 0.04);
  EXPECT_EQ(values->integer("cosmos.smoothing.iterations"), 15);
  EXPECT_EQ(values->number("cosmos.spectrum.bin_width"), 0.005);
  // One key per field, no more.
  int keys = 0;
  for (std::size_t at = text.text().find(':'); at != std::string::npos;
       at = text.text().find(':', at + 1))
    ++keys;
  EXPECT_EQ(keys, testing::parameter_field_count(CosmosParameters{}) + 6);  // + 6 section keys
}

TEST(ParameterText, LeavesOutTheNamedKeysAndSections) {
  ParameterText text;
  text.set_parameters("recognition", RecognitionParameters{}, {"search", "max_rms_mm"});
  const auto values = ParameterValues::parse(text.text());
  ASSERT_TRUE(values);
  EXPECT_EQ(values->text("recognition.selection.distance"), "euclidean");
  EXPECT_EQ(values->text("recognition.registration.estimator"), "minimum_variance");
  EXPECT_FALSE(values->number("recognition.max_rms_mm"));
  EXPECT_FALSE(values->integer("recognition.search.scoring_points"));
  EXPECT_EQ(values->integer("recognition.field_starts.scoring_points"), 100);
}

// Every field, each changed from its default, written and read back into a default struct.
template <class Parameters>
void expect_round_trip(const std::string& prefix) {
  Parameters changed;
  testing::FieldChanger changer(testing::FieldChanger::kAll);
  visit_parameters(changer, changed);
  ASSERT_GT(changer.count, 0);
  ParameterText text;
  text.set_parameters(prefix, changed);
  const auto values = ParameterValues::parse(text.text());
  ASSERT_TRUE(values);
  Parameters read;
  EXPECT_EQ(read_parameter_values(*values, prefix, read), std::nullopt);
  EXPECT_EQ(testing::parameter_leaves(read), testing::parameter_leaves(changed));
  EXPECT_NE(testing::parameter_leaves(read), testing::parameter_leaves(Parameters{}));
}

TEST(ParameterText, EveryFieldReadsBackAsWritten) {
  expect_round_trip<CosmosParameters>("cosmos");
  expect_round_trip<RecognitionParameters>("recognition");
}

TEST(ParameterText, ReadingNamesTheFirstKeyAbsentOrOfAnotherKind) {
  ParameterText text;
  text.set_parameters("cosmos", CosmosParameters{});
  text.set_text("cosmos.smoothing.iterations", "fifteen");
  CosmosParameters read;
  read.smoothing.iterations = 3;
  const auto values = ParameterValues::parse(text.text());
  ASSERT_TRUE(values);
  EXPECT_EQ(read_parameter_values(*values, "cosmos", read), "cosmos.smoothing.iterations");
  EXPECT_EQ(read.smoothing.iterations, 3);
  EXPECT_EQ(read_parameter_values(*values, "other", read), "other.fit.window_size");
  EXPECT_FALSE(ParameterValues::parse("[1, 2]"));
}

}  // namespace
}  // namespace cosmos
