// The canonical parameters text (core/io/parameters_text.hpp) a model base records: nested by
// the keys' dots, sorted, and compared key by key so a refusal names the differing key.
#include "core/io/parameters_text.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace cosmos
