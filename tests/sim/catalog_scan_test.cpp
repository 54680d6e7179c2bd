// Every part of the default catalog through the simulated scanner: each random pose yields a
// usable range image, and the same seed writes byte-identical files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "core/io/range_image_file.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "sim/seeded_random.hpp"
#include "tests/sim/scanner_test_scenes.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// One seeded random-pose scan of a part, written to `path` with its ground truth.
RangeImage scan_part(const PartEntry& part, const TriangleMesh& mesh, std::uint64_t seed,
                     const fs::path& path) {
  ScannerParameters parameters;
  parameters.seed = seed;
  const auto scene = testing::single_part_scene(mesh, random_rotation(mix_seed(seed, 0x9053)), 0.0,
                                                0.0, part.name);
  RangeImage image = testing::scan(*scene, parameters);
  if (image.width() == 0) return image;
  const Eigen::Isometry3d& T = scene->parts().front().T_belt_part;
  image.ground_truth = GroundTruthPose{part.name, T.linear(), T.translation()};
  write_range_image(image, path);
  return image;
}

TEST(CatalogScan, EveryDefaultPartScansAndRepeatsByteForByte) {
  const PartCatalog catalog =
      read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config" / "parts.yaml");
  ASSERT_EQ(catalog.parts.size(), 25u);
  for (const PartEntry& part : catalog.parts) {
    ASSERT_TRUE(fs::exists(part.mesh_path))
        << part.mesh_path << " missing: run scripts/fetch_catalog.sh";
  }
  const fs::path dir =
      fs::temp_directory_path() / ("cosmos_catalog_scan_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::uint64_t seed = 100;
  for (const PartEntry& part : catalog.parts) {
    SCOPED_TRACE(part.name);
    const TriangleMesh mesh = load_mesh(part.mesh_path, part.size_mm);
    ++seed;
    const RangeImage first = scan_part(part, mesh, seed, dir / (part.name + "_a.tiff"));
    const RangeImage second = scan_part(part, mesh, seed, dir / (part.name + "_b.tiff"));
    std::cout << "[ " << part.name << " ] " << first.width() << " x " << first.height() << ", "
              << first.count_valid() << " valid pixels\n";
    EXPECT_GE(first.count_valid(), 1000u);
    ASSERT_GT(first.width(), 0);
    ASSERT_GT(second.width(), 0);
    const std::string bytes_a = read_bytes(dir / (part.name + "_a.tiff"));
    EXPECT_FALSE(bytes_a.empty());
    EXPECT_TRUE(bytes_a == read_bytes(dir / (part.name + "_b.tiff")));
    EXPECT_EQ(read_bytes(dir / (part.name + "_a.yaml")), read_bytes(dir / (part.name + "_b.yaml")));
    // The sidecar carries the pose back exactly.
    const RangeImage loaded = read_range_image(dir / (part.name + "_a.tiff"));
    ASSERT_TRUE(loaded.ground_truth.has_value());
    EXPECT_EQ(loaded.ground_truth->part, part.name);
    EXPECT_TRUE(loaded.ground_truth->rotation == first.ground_truth->rotation);
    EXPECT_TRUE(loaded.ground_truth->translation_mm == first.ground_truth->translation_mm);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosmos
