// The visitor-driven YAML section reader (core/io/yaml_parameter_reader.hpp): every field a
// struct's visit() declares read from its key, and every bad section one line naming the
// file, the line and the key: an unknown key, a retired key (naming its replacement), a value
// out of its range or of the wrong type.
#include "core/io/yaml_parameter_reader.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/cosmos_parameters.hpp"
#include "core/input_error.hpp"
#include "core/recognition/recognizer.hpp"
#include "tests/common/config_file_test.hpp"
#include "tests/common/parameter_fields.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

enum class Colour { kRed, kGreen };

std::span<const ParameterChoice<Colour>> parameter_choices(Colour) {
  static constexpr ParameterChoice<Colour> kChoices[] = {{Colour::kRed, "red"},
                                                         {Colour::kGreen, "green"}};
  return kChoices;
}

// Every kind of field a config section holds.
struct Sample {
  double length_mm = 2.5;
  int count = 3;
  std::int64_t big = 50;
  std::uint64_t seed = 7;
  bool flag = false;
  Colour colour = Colour::kRed;
  std::string name = "a";
  fs::path file = "f.yaml";
  std::vector<std::string> names;
  RigidTransform pose;
  CosmosParameters cosmos;

  template <class Visitor>
  void visit(Visitor& v) {
    v("length_mm", length_mm, "a length", Range::above(0, 10));
    v("count", count, "a count", Range{1, 9});
    v("big", big, "a big count", Range{0, 1e15});
    v("seed", seed, "a seed");
    v("flag", flag, "a flag");
    v("colour", colour, "a colour");
    v("name", name, "a name");
    v("file", file, "a file");
    v("names", names, "some names");
    v("pose", pose, "a pose");
    v.retired("size_mm", "sample.length_mm");
    v("cosmos", cosmos, "nested");
  }
};

class YamlParameterFile : public testing::ConfigFileTest {
 protected:
  YamlParameterFile() : ConfigFileTest("sample.yaml") {}

  // The `sample:` section of the written file read into `parameters`.
  template <class Parameters>
  void read(const std::string& text, Parameters& parameters) const {
    const fs::path file = write(text);
    const YamlInputErrors errors(file);
    const YAML::Node root = errors.load_file("sample");
    YamlSectionReader section(errors, root["sample"], "sample");
    read_yaml_parameters(section, parameters);
  }

  std::string error_of(const std::string& text) const {
    try {
      Sample sample;
      read(text, sample);
    } catch (const InputError& error) {
      return error.what();
    }
    return "(no error)";
  }

  std::string where(int line, const std::string& key) const {
    return path().string() + ":" + std::to_string(line) + ": " + key + ": ";
  }
};

TEST_F(YamlParameterFile, ReadsEveryKindOfFieldAndKeepsTheDefaultsOfAbsentKeys) {
  Sample sample;
  read(
      "sample:\n"
      "  length_mm: 4\n"
      "  big: 1099511627776\n"
      "  seed: 18446744073709551615\n"
      "  flag: true\n"
      "  colour: green\n"
      "  name: b\n"
      "  file: ''\n"
      "  names: [x, y]\n"
      "  pose: {translation_mm: [1, 2, 3]}\n"
      "  cosmos:\n"
      "    smoothing: {iterations: 4}\n",
      sample);
  EXPECT_EQ(sample.length_mm, 4.0);
  EXPECT_EQ(sample.count, 3);  // absent: the default
  EXPECT_EQ(sample.big, std::int64_t{1} << 40);
  EXPECT_EQ(sample.seed, 18446744073709551615ULL);
  EXPECT_TRUE(sample.flag);
  EXPECT_EQ(sample.colour, Colour::kGreen);
  EXPECT_EQ(sample.name, "b");
  EXPECT_TRUE(sample.file.empty());
  EXPECT_EQ(sample.names, (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(sample.pose.translation_mm, Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(sample.pose.rotation.isIdentity(0.0));
  EXPECT_EQ(sample.cosmos.smoothing.iterations, 4);
  EXPECT_EQ(sample.cosmos.fit.window_size, 5);
}

TEST_F(YamlParameterFile, EveryFieldRoundTrips) {
  // Each field changed from its default, written as YAML, read back into a default struct.
  const auto expect_round_trip = [this](auto changed) {
    testing::FieldChanger changer(testing::FieldChanger::kAll, "", 2);
    visit_parameters(changer, changed);
    decltype(changed) read_back;
    read("sample:\n" + changer.yaml, read_back);
    EXPECT_EQ(testing::parameter_leaves(read_back), testing::parameter_leaves(changed))
        << changer.yaml;
    EXPECT_NE(testing::parameter_leaves(read_back), testing::parameter_leaves(decltype(changed){}));
  };
  expect_round_trip(Sample{});
  expect_round_trip(RecognitionParameters{});
}

TEST_F(YamlParameterFile, AnUnknownKeyIsRefusedNamingFileLineAndKey) {
  const std::string message = error_of("sample:\n  count: 2\n  cuont: 3\n");
  EXPECT_EQ(message.rfind(where(3, "sample.cuont") + "unknown key (known: ", 0), 0u) << message;
  const std::string nested = error_of("sample:\n  cosmos:\n    fit:\n      widow_size: 5\n");
  EXPECT_EQ(nested.rfind(where(4, "sample.cosmos.fit.widow_size") + "unknown key", 0), 0u)
      << nested;
}

TEST_F(YamlParameterFile, ARetiredKeyIsRefusedNamingItsReplacement) {
  EXPECT_EQ(error_of("sample:\n  size_mm: 2\n"),
            where(2, "sample.size_mm") + "replaced by sample.length_mm");
}

TEST_F(YamlParameterFile, AValueOutOfItsRangeOrOfTheWrongKindIsRefused) {
  EXPECT_EQ(error_of("sample:\n  length_mm: 0\n"),
            where(2, "sample.length_mm") + "must be in (0, 10], got 0");
  EXPECT_EQ(error_of("sample:\n  count: 10\n"),
            where(2, "sample.count") + "must be in [1, 9], got 10");
  EXPECT_EQ(error_of("sample:\n  count: 2.5\n"),
            where(2, "sample.count") + "expected an integer, got '2.5'");
  EXPECT_EQ(error_of("sample:\n  cosmos: {fit: {window_size: 21}}\n"),
            where(2, "sample.cosmos.fit.window_size") + "must be in [3, 15], got 21");
  EXPECT_EQ(error_of("sample:\n  colour: blue\n"),
            where(2, "sample.colour") + "expected red or green, got 'blue'");
  EXPECT_EQ(error_of("sample:\n  names: [x, x]\n"), where(2, "sample.names") + "x given twice");
  EXPECT_EQ(error_of("sample:\n  file: [a]\n"),
            where(2, "sample.file") + "expected a path, got a list");
  EXPECT_EQ(error_of("sample:\n  pose: {rotation_deg: [1, 2]}\n"),
            where(2, "sample.pose.rotation_deg") + "expected a list of 3 numbers, got a list of 2");
  EXPECT_EQ(error_of("sample:\n  cosmos: 3\n"),
            where(2, "sample.cosmos") + "expected a map, got '3'");
}

}  // namespace
}  // namespace cosmos
