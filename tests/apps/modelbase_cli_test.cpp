// `cosmos modelbase build|info` on the real binary: a tiny catalog of two procedural meshes
// (a torus and an ellipsoid, written here, so the test needs no mesh cache) seen from 12
// directions; the base's structure, byte-identical builds for any thread count, `info`, and
// one-line refusals of bad options and damaged files.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>
#include <regex>
#include <set>
#include <string>

#include "core/io/model_base_file.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

constexpr int kViews = 12;

struct RunResult {
  int exit_code = -1;  // -1: killed by a signal
  std::string out;
  std::string err;
};

std::string read_text(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// A closed surface x(u, v) on a (u, v) grid, u and v both periodic, as an OFF file.
template <class Surface>
void write_periodic_off(const fs::path& path, int nu, int nv, Surface surface) {
  std::ofstream off(path);
  off << "OFF\n" << nu * nv << " " << 2 * nu * nv << " 0\n";
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const auto p = surface(2 * std::numbers::pi * i / nu, 2 * std::numbers::pi * j / nv);
      off << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
  const auto index = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      off << "3 " << index(i, j) << " " << index(i + 1, j) << " " << index(i + 1, j + 1) << "\n";
      off << "3 " << index(i, j) << " " << index(i + 1, j + 1) << " " << index(i, j + 1) << "\n";
    }
}

class ModelBaseCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("cosmos_modelbase_cli_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    write_periodic_off(dir_ / "torus.off", 64, 32, [](double u, double v) {
      return std::array<double, 3>{(25 + 10 * std::cos(v)) * std::cos(u),
                                   (25 + 10 * std::cos(v)) * std::sin(u), 10 * std::sin(v)};
    });
    // An ellipsoid parametrized over a full v turn (each point twice; joined on loading).
    write_periodic_off(dir_ / "ellipsoid.off", 64, 32, [](double u, double v) {
      const double polar = v / 2;
      return std::array<double, 3>{30 * std::sin(polar) * std::cos(u),
                                   20 * std::sin(polar) * std::sin(u), 15 * std::cos(polar)};
    });
    std::ofstream(dir_ / "parts.yaml")
        << "parts:\n"
           "  - {name: torus, mesh: ./torus.off, size_mm: 70}\n"
           "  - {name: ellipsoid, mesh: ./ellipsoid.off, size_mm: 60, symmetric: false}\n";
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static fs::path base_path(int threads) {
    return dir_ / ("base_t" + std::to_string(threads) + ".cmb");
  }

  // The base built with 1 or 2 threads, on first use: ctest runs each test in its own process.
  static const RunResult& build(int threads) {
    std::optional<RunResult>& result = threads == 1 ? build_1_ : build_2_;
    if (!result)
      result = run("modelbase build --catalog '" + (dir_ / "parts.yaml").string() + "' --views " +
                   std::to_string(kViews) + " --threads " + std::to_string(threads) + " --out '" +
                   base_path(threads).string() + "'");
    return *result;
  }

  static RunResult run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = std::string("exec '") + COSMOS_BINARY + "' " + args + " >'" +
                                out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
  }

  static void expect_one_line_failure(const std::string& args, const std::string& needle) {
    SCOPED_TRACE("cosmos " + args);
    const RunResult result = run(args);
    EXPECT_GT(result.exit_code, 0);
    EXPECT_LT(result.exit_code, 128);
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(needle), std::string::npos)
        << "'" << needle << "' not in: " << result.err;
  }

  static inline fs::path dir_;
  static inline std::optional<RunResult> build_1_, build_2_;
};

TEST_F(ModelBaseCli, BuildsEveryPartFromTheSpreadViewsAndGroupsThem) {
  const RunResult& built = build(1);
  ASSERT_EQ(built.exit_code, 0) << built.err;
  EXPECT_NE(built.out.find("modelbase build: 2 parts, 24 views (0 measured nothing)"),
            std::string::npos)
      << built.out;
  // stderr is not a terminal here: one line per part.
  EXPECT_NE(built.err.find("part 1/2 torus scanned"), std::string::npos) << built.err;
  EXPECT_NE(built.err.find("part 2/2 ellipsoid scanned"), std::string::npos) << built.err;

  const ModelBase base = read_model_base(base_path(1));
  ASSERT_EQ(base.parts.size(), 2u);
  EXPECT_EQ(base.parts[0].name, "torus");
  EXPECT_NEAR(base.parts[0].diameter_mm, 70.0, 0.5);  // the outer diameter is the largest extent
  EXPECT_EQ(base.parts[1].mesh, "ellipsoid.off");
  EXPECT_EQ(base.catalog_hash.size(), 16u);
  EXPECT_NE(base.parameters_text.find("\"cut_level\": 0.0008"), std::string::npos);
  EXPECT_NE(base.parameters_text.find("\"stride_px\": 3"), std::string::npos);
  ASSERT_EQ(base.views.size(), 2u * kViews) << "every view of these parts measures something";
  for (std::size_t v = 0; v < base.views.size(); ++v) {
    const ModelBaseView& view = base.views[v];
    EXPECT_EQ(view.part_index, static_cast<int>(v) / kViews);
    EXPECT_EQ(view.view_index % 16, 15) << "12 <= 20 views: icosahedron face centres only";
    EXPECT_NEAR(view.direction_part.norm(), 1.0, 1e-12);
    // The part turned so the view direction points at the scanner (+z).
    EXPECT_NEAR(
        (view.T_scanner_part.rotation * view.direction_part - Eigen::Vector3d::UnitZ()).norm(), 0.0,
        1e-9);
    EXPECT_FALSE(view.cosmos.patches.empty());
    EXPECT_GT(view.registration_packed.size(), 100);
  }
  // Each part's clusters partition its views.
  for (int part = 0; part < 2; ++part) {
    std::multiset<int> members;
    for (const ViewCluster& cluster : base.clusters) {
      if (cluster.part_index != part) continue;
      EXPECT_FALSE(cluster.views.empty());
      members.insert(cluster.views.begin(), cluster.views.end());
    }
    std::multiset<int> expected;
    for (int k = 0; k < kViews; ++k) expected.insert(part * kViews + k);
    EXPECT_EQ(members, expected) << "part " << part;
  }
}

TEST_F(ModelBaseCli, AnyThreadCountGivesTheSameBytes) {
  ASSERT_EQ(build(1).exit_code, 0) << build(1).err;
  ASSERT_EQ(build(2).exit_code, 0) << build(2).err;
  const std::string one = read_text(base_path(1)), two = read_text(base_path(2));
  EXPECT_GT(one.size(), 10000u);
  EXPECT_TRUE(one == two) << "sizes " << one.size() << " and " << two.size();
}

TEST_F(ModelBaseCli, InfoPrintsPartsAndClusterCounts) {
  ASSERT_EQ(build(1).exit_code, 0) << build(1).err;
  const RunResult info = run("modelbase info '" + base_path(1).string() + "'");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const ModelBase base = read_model_base(base_path(1));
  EXPECT_NE(info.out.find("parts: 2, views: 24, clusters: " + std::to_string(base.clusters.size())),
            std::string::npos)
      << info.out;
  for (int part = 0; part < 2; ++part) {
    const auto clusters =
        std::count_if(base.clusters.begin(), base.clusters.end(),
                      [part](const ViewCluster& c) { return c.part_index == part; });
    const std::regex row(base.parts[static_cast<std::size_t>(part)].name + " +12 +" +
                         std::to_string(clusters) + " ");
    EXPECT_TRUE(std::regex_search(info.out, row)) << info.out;
  }
  EXPECT_NE(info.out.find("file size: " + std::to_string(fs::file_size(base_path(1))) + " bytes"),
            std::string::npos);
  EXPECT_NE(info.out.find("\"z_noise_mm\": 0.02"), std::string::npos) << "the parameters are shown";
}

TEST_F(ModelBaseCli, RequestedClusterCountIsKept) {
  const fs::path path = dir_ / "three.cmb";
  const RunResult build = run("modelbase build --catalog '" + (dir_ / "parts.yaml").string() +
                              "' --views 6 --clusters 3 --out '" + path.string() + "'");
  ASSERT_EQ(build.exit_code, 0) << build.err;
  const ModelBase base = read_model_base(path);
  ASSERT_EQ(base.clusters.size(), 6u);
  EXPECT_EQ(base.clusters[2].part_index, 0);
  EXPECT_EQ(base.clusters[3].part_index, 1);
  EXPECT_NE(base.parameters_text.find("\"cluster_count\": 3"), std::string::npos);
}

TEST_F(ModelBaseCli, DamagedFilesAreRefusedInOneLine) {
  ASSERT_EQ(build(1).exit_code, 0) << build(1).err;
  std::string content = read_text(base_path(1));
  const fs::path damaged = dir_ / "damaged.cmb";
  content[content.size() / 3] = static_cast<char>(content[content.size() / 3] ^ 0x01);
  std::ofstream(damaged, std::ios::binary) << content;
  expect_one_line_failure("modelbase info '" + damaged.string() + "'",
                          damaged.string() + ": corrupted: checksum mismatch");
  std::ofstream(damaged, std::ios::binary | std::ios::trunc)
      << content.substr(0, content.size() / 2);
  expect_one_line_failure("modelbase info '" + damaged.string() + "'",
                          damaged.string() + ": truncated");
}

TEST_F(ModelBaseCli, BadOptionsAreRefusedInOneLine) {
  const std::string catalog = "--catalog '" + (dir_ / "parts.yaml").string() + "' ";
  const std::string out = " --out '" + (dir_ / "never.cmb").string() + "'";
  expect_one_line_failure("modelbase build " + catalog + "--views 0" + out, "--views '0'");
  expect_one_line_failure("modelbase build " + catalog + "--views 321" + out, "--views '321'");
  expect_one_line_failure("modelbase build " + catalog + "--threads x" + out, "--threads 'x'");
  expect_one_line_failure("modelbase build " + catalog + "--threads 1000000" + out,
                          "--threads '1000000': expected an integer in [1, 1024]");
  expect_one_line_failure("modelbase build " + catalog + "--clusters 1000" + out,
                          "--clusters: grouping.cluster_count: must be in [0, 320], got 1000");
  expect_one_line_failure("modelbase build " + catalog + "--cluster-level 1e-4 --clusters 5" + out,
                          "not both");
  expect_one_line_failure("modelbase build " + catalog + "--cluster-level -1" + out,
                          "--cluster-level '-1'");
  expect_one_line_failure("modelbase build " + catalog, "missing --out");
  expect_one_line_failure("modelbase info '" + (dir_ / "absent.cmb").string() + "'",
                          "absent.cmb: cannot open");
  EXPECT_FALSE(fs::exists(dir_ / "never.cmb"));
}

}  // namespace
}  // namespace cosmos
