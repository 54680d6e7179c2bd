// cosmos.json of `cosmos inspect` on a hand-made ViewAnalysis: exact keys, values, null for NaN.
#include "core/io/cosmos_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/input_error.hpp"
#include "tests/core/hand_made_view.hpp"

namespace cosmos::testing {
namespace {

std::set<std::string> keys_of(const nlohmann::json& object) {
  std::set<std::string> keys;
  for (const auto& item : object.items()) keys.insert(item.key());
  return keys;
}

TEST(CosmosJson, HasTheContractKeysAndValues) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const std::string text = cosmos_json_text(analysis);
  EXPECT_EQ(text.find("NaN"), std::string::npos);
  const nlohmann::json json = nlohmann::json::parse(text);

  EXPECT_EQ(keys_of(json), (std::set<std::string>{"patches", "spectrum", "moments", "valid_pixels",
                                                  "visible_area_mm2", "shape_diameter_limit"}));
  EXPECT_EQ(json["valid_pixels"].get<int>(), 88);
  EXPECT_DOUBLE_EQ(json["visible_area_mm2"].get<double>(), 22.0);
  EXPECT_DOUBLE_EQ(json["shape_diameter_limit"].get<double>(), 0.25);

  const nlohmann::json& patches = json["patches"];
  ASSERT_EQ(patches.size(), 4u);
  for (const nlohmann::json& patch : patches) {
    EXPECT_EQ(keys_of(patch),
              (std::set<std::string>{"id", "area_mm2", "shape_index", "shape_index_min",
                                     "shape_index_max", "curvedness", "normal", "centroid_mm",
                                     "pixels", "planar", "neighbors"}));
  }
  EXPECT_EQ(patches[0]["id"].get<int>(), 0);
  EXPECT_DOUBLE_EQ(patches[0]["area_mm2"].get<double>(), 8.0);
  EXPECT_DOUBLE_EQ(patches[3]["area_mm2"].get<double>(), 6.0);
  EXPECT_EQ(patches[1]["neighbors"].get<std::vector<int>>(), (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(patches[3]["neighbors"].get<std::vector<int>>(), (std::vector<int>{1, 2}));
  EXPECT_EQ(patches[2]["planar"].get<bool>(), true);
  EXPECT_DOUBLE_EQ(patches[2]["shape_index"].get<double>(), kPlanarShapeIndex);
  EXPECT_DOUBLE_EQ(patches[1]["curvedness"].get<double>(), 0.2);
  EXPECT_EQ(patches[1]["normal"].get<std::vector<double>>(), (std::vector<double>{0.6, 0, 0.8}));
  EXPECT_EQ(patches[3]["centroid_mm"].get<std::vector<double>>(), (std::vector<double>{3, 2, 103}));
  EXPECT_EQ(patches[3]["pixels"].get<int>(), 24);

  const nlohmann::json& spectrum = json["spectrum"];
  EXPECT_EQ(keys_of(spectrum), (std::set<std::string>{"bin_width", "bins", "planar_fraction"}));
  EXPECT_DOUBLE_EQ(spectrum["bin_width"].get<double>(), 0.005);
  ASSERT_EQ(spectrum["bins"].size(), 200u);
  EXPECT_DOUBLE_EQ(spectrum["bins"][194].get<double>(), 8.0 / 22);
  EXPECT_DOUBLE_EQ(spectrum["planar_fraction"].get<double>(), 4.0 / 22);

  // m1..m10 only; the NaN of m10 is null.
  const nlohmann::json& moments = json["moments"];
  ASSERT_EQ(moments.size(), 10u);
  EXPECT_DOUBLE_EQ(moments[0].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(moments[2].get<double>(), -0.01);
  EXPECT_TRUE(moments[9].is_null());
}

TEST(CosmosJson, NanPatchValuesBecomeNull) {
  ViewAnalysis analysis = hand_made_view_analysis();
  analysis.view.patches[1].mean_curvedness_per_mm = std::numeric_limits<double>::quiet_NaN();
  analysis.view.patches[1].mean_normal.x() = std::numeric_limits<double>::infinity();
  const nlohmann::json json = nlohmann::json::parse(cosmos_json_text(analysis));
  EXPECT_TRUE(json["patches"][1]["curvedness"].is_null());
  EXPECT_TRUE(json["patches"][1]["normal"][0].is_null());
  EXPECT_DOUBLE_EQ(json["patches"][1]["normal"][2].get<double>(), 0.8);
}

TEST(CosmosJson, WritesTheFileAndNamesAnUnwritablePath) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cosmos_json_test";
  std::filesystem::create_directories(dir);
  write_cosmos_json(analysis, dir / "cosmos.json");
  std::ifstream file(dir / "cosmos.json");
  const nlohmann::json json = nlohmann::json::parse(file);
  EXPECT_EQ(json["patches"].size(), 4u);
  const std::filesystem::path unwritable = dir / "missing" / "cosmos.json";
  try {
    write_cosmos_json(analysis, unwritable);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(unwritable.string()), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cosmos::testing
