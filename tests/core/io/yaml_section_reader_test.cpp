// Reading one YAML map section key by key (core/io/yaml_section_reader.hpp): absent keys keep
// their defaults; wrong types, values out of range, repeated and unknown keys are one-line
// errors `file:LINE: section.key: reason`.
#include "core/io/yaml_section_reader.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

const YamlInputErrors kErrors("cell.yaml");

// The message of the InputError `run` throws ("" when it throws none).
template <class Run>
std::string error_of(Run&& run) {
  try {
    run();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

struct Tracking {
  int window = 7;
  std::int64_t offset = -3;
  std::uint64_t seed = 11;
  double gap_mm = 2.5;
  bool enabled = false;
  std::string name = "default";
};

void read_tracking(YamlSectionReader& reader, Tracking& t) {
  reader.read("window", t.window, 1, 100);
  reader.read("offset", t.offset, -1000, 1000);
  reader.read("seed", t.seed);
  reader.read("gap_mm", t.gap_mm, Range{0.0, 10.0, true, false});
  reader.read("enabled", t.enabled);
  reader.read("name", t.name);
}

// Reads the `tracking` section of `text`; the first error's message, "" when none.
std::string read_error(const std::string& text, Tracking* out = nullptr) {
  return error_of([&] {
    const YAML::Node root = YAML::Load(text);
    YamlSectionReader reader(kErrors, root["tracking"], "tracking");
    Tracking t;
    read_tracking(reader, t);
    reader.reject_unknown_keys();
    if (out) *out = t;
  });
}

TEST(YamlSectionReader, ReadsEveryTypeAndKeepsDefaultsOfAbsentKeys) {
  Tracking t;
  ASSERT_EQ(read_error("tracking:\n  window: 9\n  seed: 18446744073709551615\n  gap_mm: 10\n"
                       "  enabled: true\n  name: belt-2\n",
                       &t),
            "");
  EXPECT_EQ(t.window, 9);
  EXPECT_EQ(t.offset, -3);  // absent
  EXPECT_EQ(t.seed, 18446744073709551615u);
  EXPECT_EQ(t.gap_mm, 10.0);  // the closed end of (0, 10]
  EXPECT_TRUE(t.enabled);
  EXPECT_EQ(t.name, "belt-2");
  // No section at all, or an empty one: every default.
  for (const char* text : {"other: 1\n", "tracking:\n"}) {
    Tracking defaults;
    ASSERT_EQ(read_error(text, &defaults), "") << text;
    EXPECT_EQ(defaults.window, 7);
    EXPECT_EQ(defaults.name, "default");
  }
}

TEST(YamlSectionReader, WrongTypesAndRangesNameTheLineAndKey) {
  EXPECT_EQ(read_error("tracking:\n  window: 0\n"),
            "cell.yaml:2: tracking.window: must be in [1, 100], got 0");
  EXPECT_EQ(read_error("tracking:\n  window: 2.5\n"),
            "cell.yaml:2: tracking.window: expected an integer, got '2.5'");
  EXPECT_EQ(read_error("tracking:\n\n  offset: [1]\n"),
            "cell.yaml:3: tracking.offset: expected an integer, got a list");
  EXPECT_EQ(read_error("tracking:\n  seed: -1\n"),
            "cell.yaml:2: tracking.seed: expected a non-negative integer, got '-1'");
  EXPECT_EQ(read_error("tracking:\n  gap_mm: 0\n"),
            "cell.yaml:2: tracking.gap_mm: must be in (0, 10], got 0");
  EXPECT_EQ(read_error("tracking:\n  gap_mm: .nan\n"),
            "cell.yaml:2: tracking.gap_mm: must be in (0, 10], got .nan");
  EXPECT_EQ(read_error("tracking:\n  gap_mm: wide\n"),
            "cell.yaml:2: tracking.gap_mm: expected a number, got 'wide'");
  EXPECT_EQ(read_error("tracking:\n  enabled: 2\n"),
            "cell.yaml:2: tracking.enabled: expected true or false, got '2'");
  EXPECT_EQ(read_error("tracking:\n  name: ''\n"),
            "cell.yaml:2: tracking.name: expected a non-empty string, got ''");
}

TEST(YamlSectionReader, RepeatedUnknownKeysAndNonMapsAreRefused) {
  EXPECT_EQ(read_error("tracking:\n  window: 3\n  window: 4\n"),
            "cell.yaml:3: tracking.window: key given twice");
  EXPECT_EQ(read_error("tracking:\n  window: 3\n  windw: 4\n"),
            "cell.yaml:3: tracking.windw: unknown key (known: enabled, gap_mm, name, offset, "
            "seed, window)");
  EXPECT_EQ(read_error("tracking: [1, 2]\n"), "cell.yaml:1: tracking: expected a map, got a list");
}

TEST(YamlSectionReader, FailPointsAtTheKeyOrElseAtTheSection) {
  const YAML::Node root = YAML::Load("tracking:\n  window: 3\n  gap_mm: 4\n");
  YamlSectionReader reader(kErrors, root["tracking"], "tracking");
  EXPECT_EQ(reader.dotted("gap_mm"), "tracking.gap_mm");
  EXPECT_TRUE(reader.has("window"));
  EXPECT_FALSE(reader.has("offset"));
  EXPECT_EQ(error_of([&] { reader.fail("gap_mm", "must exceed window"); }),
            "cell.yaml:3: tracking.gap_mm: must exceed window");
  EXPECT_EQ(error_of([&] { reader.fail("offset", "required with window"); }),
            "cell.yaml:2: tracking.offset: required with window");
}

TEST(YamlSectionReader, RangeText) {
  EXPECT_EQ((Range{0, 1}).text(), "[0, 1]");
  EXPECT_EQ((Range{-2.5, 100, true, true}).text(), "(-2.5, 100)");
  EXPECT_TRUE((Range{0, 1}).contains(0.0));
  EXPECT_FALSE((Range{0, 1, true}).contains(0.0));
  EXPECT_FALSE((Range{0, 1, false, true}).contains(1.0));
  EXPECT_FALSE((Range{-1e300, 1e300}).contains(std::numeric_limits<double>::infinity()));
}

}  // namespace
}  // namespace cosmos
