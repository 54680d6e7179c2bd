// The simulated conveyor source: a seeded, bit-reproducible stream of procedural parts, each
// part's data inside the profile range the ground truth announces and empty belt in between.
#include "sim/source/simulated_source.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "scanner/conditioning_parameters.hpp"
#include "sim/procedural_meshes.hpp"
#include "tests/realtime/lcm_test_messages.hpp"
#include "tests/realtime/source_stream.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

std::vector<SimPartModel> procedural_parts() {
  return {{"ball", make_icosphere(15.0, 2), 0}, {"brick", make_box(40.0, 25.0, 12.0), 3}};
}

SimulatedSourceSettings small_settings(std::uint64_t seed) {
  SimulatedSourceSettings settings;
  settings.parts = 5;
  settings.seed = seed;
  settings.part_gap_mm = 20.0;
  return settings;
}

// Every profile of the stream from a (re)started source; next() must not allocate.
std::vector<Profile> drain(SimulatedSource& source) {
  EXPECT_EQ(source.start(), SourceStatus::kOk);
  const testing::SourceStream stream = testing::read_stream(source);
  EXPECT_EQ(stream.end, SourceStatus::kEndOfStream);
  EXPECT_EQ(stream.allocations_in_next, 0u);
  Profile slot;
  source.reserve(slot);
  EXPECT_EQ(source.next(slot), SourceStatus::kEndOfStream);  // and it stays ended
  return stream.profiles;
}

// Samples higher than the belt background (z noise is 0.02 mm, the threshold 0.5 mm).
int samples_above_belt(const Profile& profile, double background_mm) {
  int count = 0;
  for (const float z : profile.z_mm) count += !std::isnan(z) && z > background_mm ? 1 : 0;
  return count;
}

TEST(SimulatedSource, SameSeedGivesABitIdenticalStream) {
  const ScannerParameters parameters;
  SimulatedSource first(procedural_parts(), parameters, small_settings(11));
  SimulatedSource second(procedural_parts(), parameters, small_settings(11));
  const std::vector<Profile> a = drain(first);
  const std::vector<Profile> b = drain(second);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(static_cast<std::int64_t>(a.size()), first.last_profile() + 1);
  for (std::size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE(k);
    testing::expect_same_profile(a[k], b[k]);
    ASSERT_EQ(a[k].seq, k);
    ASSERT_EQ(a[k].encoder_ticks,
              static_cast<std::int64_t>(k) * parameters.encoder_ticks_per_profile);
    ASSERT_EQ(a[k].t_us, std::llround(static_cast<double>(k) * 1e6 / parameters.line_rate_hz));
  }
  // A restarted source replays the same stream.
  const std::vector<Profile> again = drain(first);
  ASSERT_EQ(again.size(), a.size());
  testing::expect_same_profile(a[a.size() / 2], again[a.size() / 2]);
}

TEST(SimulatedSource, PartsAppearInTheAnnouncedRangesWithEmptyBeltBetween) {
  ScannerParameters parameters;
  SimulatedSourceSettings settings = small_settings(3);
  settings.random_x_offset = true;
  SimulatedSource source(procedural_parts(), parameters, settings);
  const std::vector<PlacedSimPart>& parts = source.placed_parts();
  ASSERT_EQ(parts.size(), 5u);
  EXPECT_GT(parts.front().first_profile, 0);  // an empty lead-in
  const double step_mm = source.mm_per_profile();
  EXPECT_DOUBLE_EQ(step_mm, 0.4);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    SCOPED_TRACE(i);
    const PlacedSimPart& part = parts[i];
    EXPECT_TRUE(part.name == "ball" ? part.catalog_index == 0 : part.catalog_index == 3);
    EXPECT_NEAR(part.bounds_mm.min().z(), 0.0, 1e-6);  // resting on the belt
    EXPECT_LE(part.bounds_mm.max().x(), 0.5 * parameters.field_of_view_mm - 8.0 + 1e-6);
    EXPECT_GE(part.bounds_mm.min().x(), -0.5 * parameters.field_of_view_mm + 8.0 - 1e-6);
    EXPECT_LE(part.first_profile, part.last_profile);
    if (i > 0) {
      // Further upstream, and part_gap_mm of belt from the previous part.
      const double gap_mm = parts[i - 1].bounds_mm.min().y() - part.bounds_mm.max().y();
      EXPECT_NEAR(gap_mm, settings.part_gap_mm, 1e-3);
      EXPECT_GT(part.first_profile, parts[i - 1].last_profile + 40);
    }
  }
  EXPECT_EQ(source.last_profile(), parts.back().last_profile + 50);

  const std::vector<Profile> profiles = drain(source);
  ASSERT_EQ(static_cast<std::int64_t>(profiles.size()), source.last_profile() + 1);
  // Per part: profiles with data above the belt, and the first and last of them.
  std::vector<std::int64_t> with_data(parts.size(), 0);
  std::vector<std::int64_t> first_data(parts.size(), -1);
  std::vector<std::int64_t> last_data(parts.size(), -1);
  for (std::size_t k = 0; k < profiles.size(); ++k) {
    const int above = samples_above_belt(profiles[k], ConditioningParameters{}.height_threshold_mm);
    const auto index = static_cast<std::int64_t>(k);
    int owner = -1;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (index >= parts[i].first_profile && index <= parts[i].last_profile) {
        owner = static_cast<int>(i);
      }
    }
    if (owner < 0) {
      EXPECT_EQ(above, 0) << "profile " << k << " lies between parts";
    } else if (above > 0) {
      const auto i = static_cast<std::size_t>(owner);
      ++with_data[i];
      if (first_data[i] < 0) first_data[i] = index;
      last_data[i] = index;
    }
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    SCOPED_TRACE(parts[i].name);
    // The sheet meets the downstream (+y) end first; the camera, upstream, does not see a
    // surface there that faces downstream more steeply than 60°: a few profiles at the start
    // of the range may lack data, the upstream end is seen to the last profile.
    const std::int64_t range = parts[i].last_profile - parts[i].first_profile + 1;
    EXPECT_GE(static_cast<double>(with_data[i]), 0.9 * static_cast<double>(range));
    EXPECT_LE(first_data[i], parts[i].first_profile + 8);
    EXPECT_GE(last_data[i], parts[i].last_profile - 2);
  }
}

TEST(SimulatedSource, ScannedProfileRangesFindTheirPlacedPart) {
  SimulatedSource source(procedural_parts(), ScannerParameters{}, small_settings(3));
  const std::vector<PlacedSimPart>& parts = source.placed_parts();
  ASSERT_EQ(parts.size(), 5u);
  for (const PlacedSimPart& part : parts) {
    EXPECT_EQ(source.placed_part_scanned_in(part.first_profile, part.last_profile), &part);
    // A scan clipped at either end still belongs to its part.
    EXPECT_EQ(source.placed_part_scanned_in(part.first_profile + 3, part.last_profile + 2), &part);
  }
  // Rows in the empty belt between two parts belong to none; rows reaching into both belong
  // to the one they cover more.
  EXPECT_EQ(source.placed_part_scanned_in(parts[0].last_profile + 1, parts[1].first_profile - 1),
            nullptr);
  EXPECT_EQ(source.placed_part_scanned_in(parts[0].last_profile - 2, parts[1].first_profile + 9),
            &parts[1]);
  EXPECT_EQ(source.placed_part_scanned_in(parts[0].last_profile - 9, parts[1].first_profile + 2),
            &parts[0]);
}

TEST(SimulatedSource, PartNamesRestrictTheDrawAndTheSeedChangesIt) {
  const ScannerParameters parameters;
  SimulatedSourceSettings settings = small_settings(5);
  settings.parts = 12;
  std::set<std::string> names;
  SimulatedSource mixed(procedural_parts(), parameters, settings);
  for (const PlacedSimPart& part : mixed.placed_parts()) names.insert(part.name);
  EXPECT_EQ(names, (std::set<std::string>{"ball", "brick"}));

  settings.part_names = {"brick"};
  settings.pose = PoseMode::kResting;
  SimulatedSource bricks(procedural_parts(), parameters, settings);
  for (const PlacedSimPart& part : bricks.placed_parts()) {
    EXPECT_EQ(part.name, "brick");
    // A resting box lies on a face: one of its edges is vertical, so the height is an extent.
    const double height_mm = part.bounds_mm.max().z();
    EXPECT_TRUE(std::abs(height_mm - 40.0) < 1e-3 || std::abs(height_mm - 25.0) < 1e-3 ||
                std::abs(height_mm - 12.0) < 1e-3)
        << height_mm;
  }

  SimulatedSourceSettings other = small_settings(6);
  SimulatedSource reseeded(procedural_parts(), parameters, other);
  SimulatedSource original(procedural_parts(), parameters, small_settings(5));
  EXPECT_FALSE(
      reseeded.placed_parts()[0].T_belt_part.isApprox(original.placed_parts()[0].T_belt_part));
}

TEST(SimulatedSource, CameraModeRunsTheFramePath) {
  ScannerParameters parameters;
  SimulatedSourceSettings settings = small_settings(2);
  settings.parts = 1;
  settings.part_names = {"brick"};
  settings.mode = ScanMode::kCamera;
  settings.pose = PoseMode::kResting;  // a flat top face to measure
  SimulatedSource source(procedural_parts(), parameters, settings);
  const std::vector<Profile> profiles = drain(source);
  const PlacedSimPart& part = source.placed_parts().front();
  const Profile& middle =
      profiles[static_cast<std::size_t>((part.first_profile + part.last_profile) / 2)];
  const double top_mm = part.bounds_mm.max().z();
  int on_top = 0;
  for (const float z : middle.z_mm) on_top += std::abs(z - top_mm) < 0.2 ? 1 : 0;
  EXPECT_GT(on_top, 10) << "the brick's top face at " << top_mm << " mm";
  EXPECT_EQ(samples_above_belt(profiles.front(), ConditioningParameters{}.height_threshold_mm), 0);
}

// A catalog of two small OFF meshes written here and one whose file does not exist: only
// the drawn parts' meshes are read.
TEST(SimulatedSource, CatalogPartsKeepTheirCatalogIndexAndOnlyDrawnMeshesLoad) {
  const fs::path dir =
      fs::temp_directory_path() / ("cosmos_simulated_source_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "cube.off") << "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n"
                                     "1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n"
                                     "4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  std::ofstream(dir / "tetra.off") << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                      "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  std::ofstream(dir / "parts.yaml") << "parts:\n"
                                       "  - {name: ghost, mesh: ./absent.off, size_mm: 20}\n"
                                       "  - {name: cube, mesh: ./cube.off, size_mm: 30}\n"
                                       "  - {name: tetra, mesh: ./tetra.off, size_mm: 40}\n";
  const PartCatalog catalog = read_part_catalog(dir / "parts.yaml");
  SimulatedSourceSettings settings = small_settings(4);
  settings.part_names = {"tetra", "cube"};
  SimulatedSource source(catalog, ScannerParameters{}, settings);
  std::set<std::string> names;
  for (const PlacedSimPart& part : source.placed_parts()) {
    names.insert(part.name);
    EXPECT_EQ(part.catalog_index, part.name == "cube" ? 1 : 2);
    // Loaded at the catalog's size: however it is turned, the box's largest extent is at most
    // the part's diameter (vertex to vertex) and its diagonal at least that.
    const double diameter_mm = part.name == "cube" ? 30.0 * std::sqrt(3.0) : 40.0 * std::sqrt(2.0);
    EXPECT_LE(part.bounds_mm.sizes().maxCoeff(), diameter_mm + 1e-6);
    EXPECT_GE(part.bounds_mm.sizes().norm(), diameter_mm - 1e-6);
  }
  EXPECT_EQ(names, (std::set<std::string>{"cube", "tetra"}));

  settings.part_names = {"gear"};
  try {
    SimulatedSource unknown(catalog, ScannerParameters{}, settings);
    FAIL() << "no error for an unknown part";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "unknown part 'gear' in " + catalog.file.string() + " (known: ghost, cube, tetra)");
  }
  settings.part_names = {"ghost"};
  EXPECT_THROW(SimulatedSource(catalog, ScannerParameters{}, settings), InputError);
  fs::remove_all(dir);
}

TEST(SimulatedSource, BadSettingsAndUnknownNamesAreRefused) {
  const ScannerParameters parameters;
  SimulatedSourceSettings settings = small_settings(1);
  settings.part_names = {"ball", "gear"};
  try {
    SimulatedSource source(procedural_parts(), parameters, settings);
    FAIL() << "no error for an unknown part";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "unknown part 'gear' in the part list (known: ball, brick)");
  }
  settings = small_settings(1);
  settings.parts = 0;
  EXPECT_THROW(SimulatedSource(procedural_parts(), parameters, settings), std::invalid_argument);
  SimulatedSource source(procedural_parts(), parameters, small_settings(1));
  Profile slot;
  source.reserve(slot);
  EXPECT_EQ(source.next(slot), SourceStatus::kError);
  EXPECT_EQ(source.last_error(), "simulated source: next() before start()");
}

}  // namespace
}  // namespace cosmos
