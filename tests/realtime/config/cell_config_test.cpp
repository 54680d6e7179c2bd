// The cell configuration: the shipped config/cell.yaml holds the documented defaults, values
// and paths are read as given into the very settings structs the cell takes, every field of
// every section round-trips, and every bad file ends in one line `file:LINE: key: reason`
// (retired keys naming the key that replaced them).
#include "realtime/config/cell_config.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.hpp"
#include "core/parameter_range_check.hpp"
#include "tests/common/config_file_test.hpp"
#include "tests/common/parameter_fields.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class CellConfigFile : public testing::ConfigFileTest {
 protected:
  std::string error_of(const std::string& text) const {
    const std::string error =
        error_when_loading(text, [](const fs::path& file) { load_cell_config(file); });
    return error.empty() ? "(no error)" : error;
  }

  // `file:LINE: key: ` of the written file.
  std::string where(int line, const std::string& key) const {
    return path().string() + ":" + std::to_string(line) + ": " + key + ": ";
  }
};

TEST_F(CellConfigFile, ShippedConfigHoldsTheDocumentedDefaults) {
  const fs::path file = fs::path(COSMOS_SOURCE_DIR) / "config" / "cell.yaml";
  const CellConfig config = load_cell_config(file);
  const CellConfig defaults;
  EXPECT_EQ(config.file, file);
  EXPECT_EQ(config.scanner.points_per_profile, defaults.scanner.points_per_profile);
  EXPECT_EQ(config.scanner.line_rate_hz, defaults.scanner.line_rate_hz);

  EXPECT_EQ(config.cell.catalog, file.parent_path() / "parts.yaml");
  EXPECT_TRUE(fs::is_regular_file(config.cell.catalog));
  EXPECT_TRUE(config.cell.model_base.empty());
  EXPECT_EQ(config.cell.model_views, 320);
  EXPECT_TRUE(config.cell.T_cell_scanner.rotation.isIdentity(1e-15));
  EXPECT_TRUE(config.cell.T_cell_scanner.translation_mm.isZero(0.0));

  const ConditioningParameters& c = config.conditioning;
  EXPECT_EQ(c.grid_mm, defaults.conditioning.grid_mm);
  EXPECT_EQ(c.x_min_mm, defaults.conditioning.x_min_mm);
  EXPECT_EQ(c.x_max_mm, defaults.conditioning.x_max_mm);
  EXPECT_EQ(c.belt_height_mm, defaults.conditioning.belt_height_mm);
  EXPECT_EQ(c.belt_slope_x, defaults.conditioning.belt_slope_x);
  EXPECT_EQ(c.height_threshold_mm, defaults.conditioning.height_threshold_mm);
  EXPECT_EQ(c.sheet_pitch_deg, 0.0);  // an upright sheet: no de-shear
  EXPECT_EQ(c.sheet_pitch_deg, defaults.conditioning.sheet_pitch_deg);
  EXPECT_EQ(c.max_height_mm, defaults.conditioning.max_height_mm);

  const TrackingSettings& t = config.tracking;
  EXPECT_EQ(t.tracker.max_open_parts, 16);
  EXPECT_EQ(t.tracker.max_runs_per_row, 64);
  EXPECT_EQ(t.tracker.link_gap_columns, 25);
  EXPECT_EQ(t.tracker.link_gap_rows, 75);
  EXPECT_EQ(t.tracker.min_pixels, 50);
  EXPECT_EQ(t.max_part_length_mm, 300.0);
  EXPECT_EQ(config.max_part_rows(), 750);  // 300 mm of 0.4 mm profiles

  EXPECT_EQ(config.lcm.url, "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_EQ(config.lcm.pose_channel, "COSMOS_POSE");
  EXPECT_EQ(config.lcm.status_channel, "COSMOS_STATUS");
  EXPECT_EQ(config.lcm.profile_channel, "COSMOS_PROFILE");
  EXPECT_FALSE(config.lcm.publishing.publish_profiles);
  EXPECT_EQ(config.lcm.publishing.status_period_s, 1.0);

  EXPECT_EQ(config.realtime.threads.thread.sched_fifo_priority, 0);
  EXPECT_EQ(config.realtime.threads.thread.cpu, -1);
  EXPECT_FALSE(config.realtime.threads.thread.lock_memory);
  EXPECT_EQ(config.realtime.threads.profile_ring_slots, 4096);
  EXPECT_EQ(config.realtime.parts.builders, 8);
  EXPECT_EQ(config.realtime.parts.part_queue_slots, 8);
  EXPECT_EQ(config.realtime.threads.pose_queue_slots, 32);

  EXPECT_EQ(config.sim_source.parts, 20);
  EXPECT_EQ(config.sim_source.seed, 7u);
  EXPECT_EQ(config.sim_source.part_gap_mm, 40.0);
  EXPECT_EQ(config.sim_source.pose, PoseMode::kRandom);
  EXPECT_FALSE(config.sim_source.random_x_offset);
  EXPECT_EQ(config.sim_source.mode, ScanMode::kProfile);
  EXPECT_TRUE(config.sim_source.part_names.empty());

  // Field by field, the whole config is the defaults (paths resolved against the file).
  CellConfig resolved = defaults;
  resolved.cell.catalog = file.parent_path() / defaults.cell.catalog;
  EXPECT_EQ(testing::parameter_leaves(config), testing::parameter_leaves(resolved));
}

TEST_F(CellConfigFile, EveryDefaultIsInItsDeclaredRange) {
  EXPECT_EQ(first_out_of_range(CellConfig{}, ""), std::nullopt);
}

TEST_F(CellConfigFile, EveryFieldOfEverySectionRoundTrips) {
  // Every field changed from its default, written as YAML and read back.
  CellConfig changed;
  testing::FieldChanger changer(testing::FieldChanger::kAll);
  visit_parameters(changer, changed);
  EXPECT_EQ(changer.count, testing::parameter_field_count(CellConfig{}));
  const CellConfig config = load_cell_config(write(changer.yaml));
  changed.cell.catalog = dir_ / changed.cell.catalog;
  changed.cell.model_base = dir_ / changed.cell.model_base;
  EXPECT_EQ(testing::parameter_leaves(config), testing::parameter_leaves(changed)) << changer.yaml;
}

TEST_F(CellConfigFile, EmptyFileGivesTheDefaultsWithTheCatalogBesideIt) {
  const CellConfig config = load_cell_config(write(""));
  EXPECT_EQ(config.cell.catalog, dir_ / "parts.yaml");
  EXPECT_EQ(config.realtime.threads.profile_ring_slots, 4096);
  EXPECT_EQ(config.scanner.points_per_profile, 640);
}

TEST_F(CellConfigFile, ReadsEveryKindOfValue) {
  const CellConfig config = load_cell_config(
      write("scanner: {points_per_profile: 1280}\n"
            "cell:\n"
            "  catalog: ../catalogs/parts.yaml\n"
            "  model_base: /var/cache/cosmos/model.cmb\n"
            "  model_views: 80\n"
            "  T_cell_scanner:\n"
            "    rotation_deg: [0, 0, 90]\n"
            "    translation_mm:\n"
            "      - 100\n"
            "      - -20.5\n"
            "      - 600\n"
            "conditioning: {grid_mm: 0.5, x_min_mm: -100, x_max_mm: 100, belt_slope_x: 0.01}\n"
            "tracking: {min_pixels: 200, max_part_length_mm: 150}\n"
            "lcm: {url: 'udpm://239.255.76.67:7667?ttl=1', pose_channel: POSES, publish_profiles: "
            "true, status_period_s: 0.5}\n"
            "realtime: {sched_fifo_priority: 80, cpu: 1, lock_memory: true, part_builders: 3, "
            "part_queue_slots: 4}\n"
            "sim_source: {parts: 3, seed: 18446744073709551615, pose: resting, part_names: [bunny, "
            "cow]}\n"));
  EXPECT_EQ(config.scanner.points_per_profile, 1280);
  EXPECT_EQ(config.cell.catalog, dir_ / "../catalogs/parts.yaml");
  EXPECT_EQ(config.cell.model_base, fs::path("/var/cache/cosmos/model.cmb"));
  EXPECT_EQ(config.cell.model_views, 80);
  // Rz(90): the scanner's x axis is the cell's y axis.
  const Eigen::Vector3d x_in_cell = config.cell.T_cell_scanner.rotate(Eigen::Vector3d::UnitX());
  EXPECT_NEAR(x_in_cell.y(), 1.0, 1e-12);
  EXPECT_NEAR(x_in_cell.x(), 0.0, 1e-12);
  EXPECT_EQ(config.cell.T_cell_scanner.translation_mm, Eigen::Vector3d(100, -20.5, 600));
  EXPECT_EQ(config.conditioning.grid_mm, 0.5);
  EXPECT_EQ(config.conditioning.x_min_mm, -100.0);
  EXPECT_EQ(config.conditioning.belt_slope_x, 0.01);
  EXPECT_EQ(config.conditioning.height_threshold_mm, 0.5);  // not given: default
  EXPECT_EQ(config.tracking.tracker.min_pixels, 200);
  EXPECT_EQ(config.max_part_rows(), 375);
  EXPECT_EQ(config.lcm.url, "udpm://239.255.76.67:7667?ttl=1");
  EXPECT_EQ(config.lcm.pose_channel, "POSES");
  EXPECT_EQ(config.lcm.status_channel, "COSMOS_STATUS");
  EXPECT_TRUE(config.lcm.publishing.publish_profiles);
  EXPECT_EQ(config.lcm.publishing.status_period_s, 0.5);
  EXPECT_EQ(config.realtime.threads.thread.sched_fifo_priority, 80);
  EXPECT_EQ(config.realtime.threads.thread.cpu, 1);
  EXPECT_TRUE(config.realtime.threads.thread.lock_memory);
  EXPECT_EQ(config.realtime.parts.builders, 3);
  EXPECT_EQ(config.realtime.parts.part_queue_slots, 4);
  EXPECT_EQ(config.sim_source.parts, 3);
  EXPECT_EQ(config.sim_source.seed, 18446744073709551615ULL);
  EXPECT_EQ(config.sim_source.pose, PoseMode::kResting);
  ASSERT_EQ(config.sim_source.part_names.size(), 2u);
  EXPECT_EQ(config.sim_source.part_names[1], "cow");
}

struct BadFile {
  const char* text;
  int line;
  const char* key;
  const char* reason;  // the start of the reason
};

TEST_F(CellConfigFile, EveryBadValueNamesItsLineAndKey) {
  const BadFile cases[] = {
      {"scanner:\n  z_noise_mm: 0.02\nrobot:\n  ip: 1\n", 3, "robot", "unknown section (known: "},
      {"tracking:\n  max_open_parts: 4\n  max_open_part: 3\n", 3, "tracking.max_open_part",
       "unknown key (known: "},
      {"lcm:\n\n  publish_profiles: maybe\n", 3, "lcm.publish_profiles",
       "expected true or false, got 'maybe'"},
      {"realtime:\n  cpu: 1.5\n", 2, "realtime.cpu", "expected an integer, got '1.5'"},
      {"realtime:\n  sched_fifo_priority: 120\n", 2, "realtime.sched_fifo_priority",
       "must be in [0, 99], got 120"},
      {"realtime: {cpu: -2}\n", 1, "realtime.cpu", "must be in [-1, 1023], got -2"},
      {"realtime:\n  part_builders: 0\n", 2, "realtime.part_builders", "must be in [1, 64], got 0"},
      {"cell:\n  model_views: 321\n", 2, "cell.model_views", "must be in [1, 320], got 321"},
      {"cell:\n  T_cell_scanner:\n    rotation_deg: [1, 2]\n", 3,
       "cell.T_cell_scanner.rotation_deg", "expected a list of 3 numbers, got a list of 2"},
      {"cell:\n  T_cell_scanner:\n    translation_mm: [0, x, 0]\n", 3,
       "cell.T_cell_scanner.translation_mm", "expected a number, got 'x'"},
      {"cell:\n  T_cell_scanner:\n    translation: [0, 0, 0]\n", 3,
       "cell.T_cell_scanner.translation", "unknown key"},
      {"cell:\n  catalog: [a, b]\n", 2, "cell.catalog", "expected a path, got a list"},
      {"conditioning:\n  grid_mm: 0\n", 2, "conditioning.grid_mm", "must be in (0, 100], got 0"},
      {"conditioning:\n  x_min_mm: 10\n  x_max_mm: 5\n", 3, "conditioning.x_max_mm",
       "x_max_mm must exceed x_min_mm"},
      {"conditioning:\n  x_min_mm: 200\n", 2, "conditioning.x_min_mm",
       "x_max_mm must exceed x_min_mm"},
      {"conditioning:\n  sheet_pitch_deg: 10\n  max_height_mm: 10000\n", 3,
       "conditioning.max_height_mm", "gives a de-shear window of more than 4096 rows"},
      {"conditioning:\n  sheet_pitch_deg: 10.5\n", 2, "conditioning.sheet_pitch_deg",
       "must be in [-10, 10], got 10.5"},
      {"lcm:\n  status_period_s: .nan\n", 2, "lcm.status_period_s", "must be in (0, 3600]"},
      {"lcm:\n  url: ''\n", 2, "lcm.url", "expected a non-empty string, got ''"},
      {"tracking: 5\n", 1, "tracking", "expected a map, got '5'"},
      {"tracking:\n  min_pixels: 1\n  min_pixels: 2\n", 3, "tracking.min_pixels",
       "key given twice"},
      {"sim_source:\n  pose: sideways\n", 2, "sim_source.pose",
       "expected random or resting, got 'sideways'"},
      {"sim_source:\n  seed: -1\n", 2, "sim_source.seed", "expected a non-negative integer"},
      {"sim_source:\n  part_names:\n    - bunny\n    - bunny\n", 4, "sim_source.part_names",
       "bunny given twice"},
      {"scanner:\n  bogus: 1\n", 2, "scanner.bogus", "unknown key"},
      {"sim_source:\n  parts: 0\n", 2, "sim_source.parts", "must be in [1, 1000000], got 0"},
      {"sim_source:\n  mode: laser\n", 2, "sim_source.mode",
       "expected profile or camera, got 'laser'"},
      {"tracking:\n  min_pixels: 1\nscanner: {}\ntracking: {}\n", 4, "tracking",
       "section given twice"},
      // One concept, one key: the model views' and the live scans' belt threshold and the
      // fit's depth jump (which the cell takes from its model base).
      {"scanner:\n  background_height_mm: 0.5\n", 2, "scanner.background_height_mm",
       "replaced by conditioning.height_threshold_mm"},
      {"conditioning:\n  grid_mm: 0.4\n  depth_jump_mm: 3\n", 3, "conditioning.depth_jump_mm",
       "replaced by cosmos.fit.depth_jump_mm, which the cell takes from its model base"},
  };
  for (const BadFile& bad : cases) {
    const std::string message = error_of(bad.text);
    EXPECT_EQ(message.rfind(where(bad.line, bad.key) + bad.reason, 0), 0u)
        << "file:\n"
        << bad.text << "message: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST_F(CellConfigFile, MissingFileAndSyntaxErrorNameTheFile) {
  const fs::path missing = dir_ / "absent.yaml";
  try {
    load_cell_config(missing);
    FAIL() << "no error for a missing file";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), missing.string() + ": config file not found");
  }
  const std::string syntax = error_of("cell:\n  catalog: [a, b\n");
  EXPECT_EQ(syntax.rfind((dir_ / "cell.yaml").string() + ":", 0), 0u) << syntax;
  EXPECT_EQ(syntax.find('\n'), std::string::npos) << syntax;
}

}  // namespace
}  // namespace cosmos
