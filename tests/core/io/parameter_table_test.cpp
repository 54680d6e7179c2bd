// The documentation table of a parameter struct (core/io/parameter_table.hpp): a row per
// visited key with its default, description and range, nested keys dotted, retired keys with
// their replacements, as Markdown.
#include "core/io/parameter_table.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/cosmos_parameters.hpp"
#include "core/registration/view_registration.hpp"

namespace cosmos {
namespace {

struct Documented {
  double depth_jump_mm = 3.0;
  bool bicubic = true;
  std::string url = "udpm://host";
  RegistrationParameters registration;
  template <class Visitor>
  void visit(Visitor& v) {
    v("depth_jump_mm", depth_jump_mm, "|dz| across an edge, mm", Range::above(0, 10));
    v("bicubic", bicubic, "a flag");
    v("url", url, "a text");
    v.retired("jump_mm", "depth_jump_mm");
    v("registration", registration, "nested");
  }
};

TEST(ParameterTable, RowsHoldKeyDefaultDescriptionAndRange) {
  const ParameterTable table = ParameterTable::of(Documented{});
  ASSERT_GE(table.rows().size(), 4u);
  const ParameterRow& jump = table.rows()[0];
  EXPECT_EQ(jump.key, "depth_jump_mm");
  EXPECT_EQ(jump.default_value, "3");
  EXPECT_EQ(jump.description, "|dz| across an edge, mm");
  EXPECT_EQ(jump.valid, "(0, 10]");
  EXPECT_EQ(table.rows()[1].default_value, "true");
  EXPECT_EQ(table.rows()[1].valid, "");
  EXPECT_EQ(table.rows()[2].default_value, "\"udpm://host\"");
  const ParameterRow& estimator = table.rows()[3];
  EXPECT_EQ(estimator.key, "registration.estimator");
  EXPECT_EQ(estimator.default_value, "minimum_variance");
  EXPECT_EQ(estimator.valid, "chen_medioni or minimum_variance");
  ASSERT_EQ(table.retired().size(), 1u);
  EXPECT_EQ(table.retired()[0].key, "jump_mm");
}

TEST(ParameterTable, MarkdownHasARowPerKeyWithPipesEscaped) {
  const std::string markdown = ParameterTable::of(Documented{}).markdown();
  EXPECT_EQ(markdown.rfind("| key | default | description | range |\n|---|---|---|---|\n", 0), 0u);
  EXPECT_NE(markdown.find("| `depth_jump_mm` | `3` | \\|dz\\| across an edge, mm | (0, 10] |\n"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("\nRetired: `jump_mm`, replaced by depth_jump_mm.\n"), std::string::npos);
  const std::size_t rows = ParameterTable::of(Documented{}).rows().size();
  std::size_t lines = 0;
  for (char c : markdown) lines += c == '\n';
  EXPECT_EQ(lines, 2 + rows + 2);  // header, rows, a blank line and the retired key
}

TEST(ParameterTable, EveryCosmosParameterHasARowWithADescription) {
  const ParameterTable table = ParameterTable::of(CosmosParameters{});
  EXPECT_EQ(table.rows().size(), 22u);
  for (const ParameterRow& row : table.rows()) {
    EXPECT_FALSE(row.description.empty()) << row.key;
    if (row.key != "fit.bicubic") {
      EXPECT_FALSE(row.valid.empty()) << row.key << ": every COSMOS number has a range";
    }
  }
  EXPECT_EQ(table.rows()[5].key, "smoothing.iterations");
  EXPECT_EQ(table.rows()[5].default_value, "15");
}

}  // namespace
}  // namespace cosmos
