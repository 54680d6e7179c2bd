// The model-base file (core/io/model_base_file.hpp): a hand-made base of 2 parts survives
// write -> read field for field, and every kind of damage is refused with one line naming the
// file and the reason.
#include "core/io/model_base_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>

#include "core/input_error.hpp"
#include "core/io/parameters_text.hpp"
#include "core/io/xxh64.hpp"
#include "tests/core/hand_made_view.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// A quadric relief of 0.4 mm pixels with a hole, so the control-point grid has gaps.
RangeImage relief(double tilt) {
  RangeImage image(40, 30, 0.4, 0.4);
  image.origin_x_mm = -8.0;
  image.origin_y_mm = 3.0;
  std::mt19937 generator(7);
  std::normal_distribution<float> noise(0.0f, 0.02f);
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column) {
      const double x = image.x_mm(column), y = image.y_mm(row);
      const bool hole = std::hypot(column - 25, row - 12) < 5;
      image.z_mm(column, row) =
          hole ? std::nanf("")
               : static_cast<float>(50 + tilt * x + 0.01 * x * x - 0.02 * x * y + 0.005 * y * y) +
                     noise(generator);
    }
  return image;
}

std::string parameters(double noise_mm) {
  ParameterText text;
  text.set_integer("cosmos.fit.window_size", 5);
  text.set_number("scanner.z_noise_mm", noise_mm);
  text.set_flag("registration.quadric_fit", true);
  text.set_text("views.directions", "icosahedron-2");
  return text.text();
}

ModelBase hand_made_base() {
  ModelBase base;
  base.catalog_hash = "0123456789abcdef";
  base.parameters_text = parameters(0.02);
  base.parts = {{"cow", "cow.off", 120, 131.5, false, {}, {}, {}, {}, {}},
                {"spool", "spool.off", 70, 74.25, true, {}, {}, {}, {}, {}}};
  base.parts[0].resting_poses = {{rotation_from_xyz_angles_deg(180, 0, 0), 21.5, 0.625},
                                 {rotation_from_xyz_angles_deg(90, 0, 0), 30.25, 0.375}};
  base.parts[0].hull_vertices_mm = {{-60, -20, -21.5}, {60, 25, 30}, {0, -30, 5}};
  const CosmosView cosmos = testing::hand_made_view_analysis().view;
  for (int k = 0; k < 5; ++k) {
    ModelBaseView view;
    view.part_index = k < 3 ? 0 : 1;
    view.view_index = 16 * k + 15;
    view.direction_part = Eigen::Vector3d(0.1 * k, -0.2, 1.0).normalized();
    view.T_scanner_part.rotation = rotation_from_xyz_angles_deg(10.0 * k, -5.0, 30.0);
    view.T_scanner_part.translation_mm = {1.5 * k, -2.0, 33.0};
    view.cosmos = cosmos;
    view.cosmos.patches[1].area_mm2 += k;
    for (int m = 0; m < kSpectrumMoments + 1; ++m)
      view.moments[static_cast<std::size_t>(m)] = 0.3 + 0.01 * k - 1e-3 * m;
    RegistrationPointParameters registration;
    registration.stride_px = 2;
    view.registration = build_registration_points(relief(0.05 * k), registration).points;
    base.views.push_back(std::move(view));
  }
  base.clusters = {{0, {0, 2}, {}}, {0, {1}, {}}, {1, {3, 4}, {}}};
  for (ViewCluster& cluster : base.clusters) cluster.centroid.fill(0.25 + cluster.views.front());
  return base;
}

class ModelBaseFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cosmos_mbfile_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    path_ = dir_ / "base.cmb";
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string bytes() const {
    std::ifstream file(path_, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  }
  void put_bytes(const std::string& content) const {
    std::ofstream(path_, std::ios::binary | std::ios::trunc) << content;
  }
  // The one-line refusal of read_model_base, or "" when it loads.
  std::string refusal(const std::optional<std::string>& expected = std::nullopt) const {
    try {
      read_model_base(path_, expected);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }
  void expect_refusal(const std::string& needle,
                      const std::optional<std::string>& expected = std::nullopt) const {
    const std::string message = refusal(expected);
    EXPECT_EQ(message.rfind(path_.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(needle), std::string::npos) << "'" << needle << "' not in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }

  fs::path dir_, path_;
};

void expect_same_patches(const CosmosView& read, const CosmosView& written) {
  EXPECT_EQ(read.visible_area_mm2, written.visible_area_mm2);
  ASSERT_EQ(read.patches.size(), written.patches.size());
  for (std::size_t p = 0; p < read.patches.size(); ++p) {
    const Csmp &a = read.patches[p], &b = written.patches[p];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.area_mm2, b.area_mm2);
    EXPECT_EQ(a.mean_normal, b.mean_normal);
    EXPECT_EQ(a.shape_index, b.shape_index);
    EXPECT_EQ(a.shape_index_min, b.shape_index_min);
    EXPECT_EQ(a.shape_index_max, b.shape_index_max);
    EXPECT_EQ(a.mean_curvedness_per_mm, b.mean_curvedness_per_mm);
    EXPECT_EQ(a.centroid_mm, b.centroid_mm);
    EXPECT_EQ(a.pixels, b.pixels);
    EXPECT_EQ(a.planar, b.planar);
    ASSERT_EQ(a.neighbors.size(), b.neighbors.size());
    for (std::size_t n = 0; n < a.neighbors.size(); ++n) {
      EXPECT_EQ(a.neighbors[n].patch, b.neighbors[n].patch);
      EXPECT_EQ(a.neighbors[n].shared_boundary_pixels, b.neighbors[n].shared_boundary_pixels);
    }
  }
  ASSERT_EQ(read.gauss_map.size(), written.gauss_map.size());
  for (std::size_t g = 0; g < read.gauss_map.size(); ++g) {
    EXPECT_EQ(read.gauss_map[g].direction, written.gauss_map[g].direction);
    ASSERT_EQ(read.gauss_map[g].terms.size(), written.gauss_map[g].terms.size());
    for (std::size_t t = 0; t < read.gauss_map[g].terms.size(); ++t) {
      const SupportTerm &a = read.gauss_map[g].terms[t], &b = written.gauss_map[g].terms[t];
      EXPECT_EQ(a.shape_index, b.shape_index);
      EXPECT_EQ(a.area_mm2, b.area_mm2);
      EXPECT_EQ(a.curvedness_area, b.curvedness_area);
      EXPECT_EQ(a.patches, b.patches);
    }
  }
}

// Each fit coefficient within half its fixed-point step (packed_registration_points.hpp),
// the grid exactly; normals are the fit's tangent plane's.
void expect_same_registration(const RegistrationPoints& read, const RegistrationPoints& written) {
  EXPECT_EQ(read.grid_width, written.grid_width);
  EXPECT_EQ(read.grid_height, written.grid_height);
  EXPECT_EQ(read.origin_x_mm, written.origin_x_mm);
  EXPECT_EQ(read.origin_y_mm, written.origin_y_mm);
  EXPECT_EQ(read.spacing_x_mm, written.spacing_x_mm);
  EXPECT_EQ(read.spacing_y_mm, written.spacing_y_mm);
  EXPECT_EQ(read.cell_point, written.cell_point);
  EXPECT_EQ(read.fit_cofactor, written.fit_cofactor);
  EXPECT_EQ(read.z_noise_sigma_mm, written.z_noise_sigma_mm);
  ASSERT_EQ(read.size(), written.size());
  const double noise_mm = std::max(written.z_noise_sigma_mm, kMinNoiseSigmaMm);
  for (int c = 0; c < kSurfaceCoefficients; ++c) {
    const double step = kStepPerSigma * noise_mm * std::sqrt(written.fit_cofactor(c, c));
    EXPECT_GT(step, 0.0);
    EXPECT_LE((read.surface.row(c) - written.surface.row(c)).cwiseAbs().maxCoeff(),
              0.5 * step * (1 + 1e-9))
        << c;
  }
  EXPECT_LT(kStepPerSigma * noise_mm * std::sqrt(written.fit_cofactor(kHeight, kHeight)), 0.01);
  for (int i = 0; i < read.size(); ++i) {
    EXPECT_NEAR(read.position_mm(0, i), written.position_mm(0, i), 1e-9);
    EXPECT_NEAR(read.position_mm(1, i), written.position_mm(1, i), 1e-9);
    EXPECT_NEAR(read.position_mm(2, i), written.position_mm(2, i), 0.005);
    const Eigen::Vector3d tangent_normal =
        Eigen::Vector3d(-read.surface(kSlopeX, i), -read.surface(kSlopeY, i), 1.0).normalized();
    EXPECT_NEAR((read.normal.col(i) - tangent_normal).norm(), 0.0, 1e-12);
  }
}

TEST_F(ModelBaseFile, RoundTripKeepsEveryField) {
  const ModelBase written = hand_made_base();
  write_model_base(written, path_);
  const ModelBase read = read_model_base(path_, written.parameters_text);

  EXPECT_EQ(read.catalog_hash, written.catalog_hash);
  EXPECT_EQ(read.parameters_text, written.parameters_text);
  ASSERT_EQ(read.parts.size(), 2u);
  for (std::size_t p = 0; p < 2; ++p) {
    EXPECT_EQ(read.parts[p].name, written.parts[p].name);
    EXPECT_EQ(read.parts[p].mesh, written.parts[p].mesh);
    EXPECT_EQ(read.parts[p].size_mm, written.parts[p].size_mm);
    EXPECT_EQ(read.parts[p].diameter_mm, written.parts[p].diameter_mm);
    EXPECT_EQ(read.parts[p].symmetric, written.parts[p].symmetric);
  }
  ASSERT_EQ(read.views.size(), written.views.size());
  for (std::size_t v = 0; v < read.views.size(); ++v) {
    SCOPED_TRACE("view " + std::to_string(v));
    const ModelBaseView &a = read.views[v], &b = written.views[v];
    EXPECT_EQ(a.part_index, b.part_index);
    EXPECT_EQ(a.view_index, b.view_index);
    EXPECT_EQ(a.direction_part, b.direction_part);
    EXPECT_EQ(a.T_scanner_part.rotation, b.T_scanner_part.rotation);
    EXPECT_EQ(a.T_scanner_part.translation_mm, b.T_scanner_part.translation_mm);
    EXPECT_EQ(a.moments, b.moments);
    expect_same_patches(a.cosmos, b.cosmos);
    EXPECT_EQ(a.registration.size(), 0) << "a loaded base keeps the packed form only";
    EXPECT_GT(a.registration_packed.size(), 100);
    expect_same_registration(unpack_registration_points(a.registration_packed), b.registration);
  }
  ASSERT_EQ(read.clusters.size(), written.clusters.size());
  for (std::size_t c = 0; c < read.clusters.size(); ++c) {
    EXPECT_EQ(read.clusters[c].part_index, written.clusters[c].part_index);
    EXPECT_EQ(read.clusters[c].views, written.clusters[c].views);
    EXPECT_EQ(read.clusters[c].centroid, written.clusters[c].centroid);
  }

  // A loaded base writes back to the same bytes: the packed form is stored as it is.
  const std::string first = bytes();
  write_model_base(read, path_);
  EXPECT_EQ(bytes(), first);
}

TEST_F(ModelBaseFile, TruncatedFileIsRefused) {
  write_model_base(hand_made_base(), path_);
  const std::string content = bytes();
  put_bytes(content.substr(0, content.size() - 100));
  expect_refusal("truncated: " + std::to_string(content.size() - 100) + " of " +
                 std::to_string(content.size()));
  put_bytes(content.substr(0, 20));
  expect_refusal("truncated: 20 bytes");
  put_bytes("");
  expect_refusal("truncated: 0 bytes");
}

TEST_F(ModelBaseFile, FlippedPayloadByteIsACorruptedChecksum) {
  write_model_base(hand_made_base(), path_);
  std::string content = bytes();
  content[content.size() / 2] = static_cast<char>(content[content.size() / 2] ^ 0x10);
  put_bytes(content);
  expect_refusal("corrupted: checksum mismatch");
}

// Damage behind a matching checksum (a writer bug, a crafted file) is caught by the
// FlatBuffers verifier and the base's invariants: never a crash, never a silent load of
// garbage indices.
TEST_F(ModelBaseFile, DamageBehindAValidChecksumIsCaughtByTheVerifier) {
  write_model_base(hand_made_base(), path_);
  const std::string original = bytes();
  const auto with_checksum = [](std::string content) {
    const std::uint64_t checksum =
        xxh64(content.data() + kModelBaseHeaderBytes, content.size() - kModelBaseHeaderBytes);
    for (int k = 0; k < 8; ++k)
      content[24 + static_cast<std::size_t>(k)] = static_cast<char>(checksum >> (8 * k));
    return content;
  };
  std::string garbage = original;
  for (std::size_t k = kModelBaseHeaderBytes; k < garbage.size(); ++k)
    garbage[k] = static_cast<char>(k * 31);
  put_bytes(with_checksum(garbage));
  expect_refusal("corrupted: no CSMB payload identifier");

  std::mt19937 generator(3);
  std::uniform_int_distribution<std::size_t> position(kModelBaseHeaderBytes, original.size() - 1);
  int refused = 0;
  for (int trial = 0; trial < 120; ++trial) {
    std::string damaged = original;
    for (int flip = 0; flip < 4; ++flip)
      damaged[position(generator)] ^= static_cast<char>(1 + trial % 255);
    put_bytes(with_checksum(damaged));
    const std::string message = refusal();
    if (message.empty()) continue;  // flipped payload values, e.g. an area: still a valid base
    ++refused;
    EXPECT_NE(message.find(": corrupted: "), std::string::npos) << message;
  }
  EXPECT_GT(refused, 0);
}

// A header announcing an empty payload: the identifier check read 4 bytes past the file.
TEST_F(ModelBaseFile, HeaderWithoutPayloadIsRefused) {
  write_model_base(hand_made_base(), path_);
  std::string content = bytes().substr(0, kModelBaseHeaderBytes);
  for (int k = 0; k < 8; ++k) content[16 + static_cast<std::size_t>(k)] = 0;  // payload bytes
  const std::uint64_t checksum = xxh64(content.data(), 0);
  for (int k = 0; k < 8; ++k)
    content[24 + static_cast<std::size_t>(k)] = static_cast<char>(checksum >> (8 * k));
  put_bytes(content);
  expect_refusal("corrupted: payload of 0 bytes, shorter than its 8-byte start");
}

TEST_F(ModelBaseFile, OtherFormatVersionIsRefused) {
  write_model_base(hand_made_base(), path_);
  std::string content = bytes();
  content[8] = static_cast<char>(ModelBase::kFormatVersion + 1);
  put_bytes(content);
  expect_refusal("format version " + std::to_string(ModelBase::kFormatVersion + 1) +
                 ", this build reads version " + std::to_string(ModelBase::kFormatVersion));
}

TEST_F(ModelBaseFile, NotAModelBaseIsRefused) {
  put_bytes("solid cube\nfacet normal 0 0 1\n");
  expect_refusal("not a COSMOS model base");
}

TEST_F(ModelBaseFile, OtherParametersAreRefusedNamingTheKey) {
  write_model_base(hand_made_base(), path_);
  EXPECT_EQ(refusal(parameters(0.02)), "");
  expect_refusal(
      "built with other parameters: scanner.z_noise_mm is 0.02 in the file, 0.05 expected",
      parameters(0.05));
}

TEST_F(ModelBaseFile, MissingFileIsRefused) {
  fs::remove(path_);
  expect_refusal("cannot open");
}

// A base written with absurd values (a writer bug or a crafted file: the checksum matches)
// passes the FlatBuffers verifier; each value the recognizer trusts is refused with one line
// naming the view and the value, instead of reaching the pose search's distance field.
TEST_F(ModelBaseFile, AbsurdValuesBehindAValidChecksumAreRefusedNamingThem) {
  const auto refusal_of = [&](const std::function<void(ModelBase&)>& damage) {
    ModelBase base = hand_made_base();
    for (ModelBaseView& view : base.views) {
      view.registration_packed = pack_registration_points(view.registration);
      view.registration = {};
    }
    damage(base);
    write_model_base(base, path_);
    return refusal();
  };
  const auto expect_refused = [&](const std::function<void(ModelBase&)>& damage,
                                  const std::string& needle) {
    const std::string message = refusal_of(damage);
    EXPECT_EQ(message.rfind(path_.string() + ": corrupted: ", 0), 0u) << message;
    EXPECT_NE(message.find(needle), std::string::npos) << "'" << needle << "' not in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  };
  EXPECT_EQ(refusal_of([](ModelBase&) {}), "");
  expect_refused([](ModelBase& b) { b.views[2].T_scanner_part.translation_mm.x() = 1e300; },
                 "view 2: T_scanner_part translation_mm.x is 1e+300, expected within +-10000");
  expect_refused([](ModelBase& b) { b.views[1].T_scanner_part.rotation(0, 0) = 3; },
                 "view 1: T_scanner_part rotation's |R^T R - I|");
  expect_refused([](ModelBase& b) { b.views[0].registration_packed.origin_y_mm = std::nan(""); },
                 "view 0: registration origin_y_mm is nan");
  expect_refused([](ModelBase& b) { b.views[4].registration_packed.spacing_x_mm = 0; },
                 "view 4: registration spacing_x_mm is 0");
  expect_refused(
      [](ModelBase& b) { b.views[2].registration_packed.coefficients[kSlopeX].step = 1e300; },
      "view 2: registration slope x step is 1e+300");
  expect_refused(
      [](ModelBase& b) { b.views[1].registration_packed.coefficients[kHeight].low = -(1 << 28); },
      "view 1: registration height_mm lower bound is -");
  expect_refused(
      [](ModelBase& b) {
        b.views[3].direction_part = {0, 0, 7};
      },
      "view 3: direction_part length is 7");
  expect_refused([](ModelBase& b) { b.parts[1].size_mm = -1; }, "part 1: size_mm is -1");
  expect_refused([](ModelBase& b) { b.parts[0].resting_poses[1].R_belt_part(1, 2) = 0.5; },
                 "part 0 resting pose 1: R_belt_part rotation's |R^T R - I|");
  expect_refused([](ModelBase& b) { b.parts[0].resting_poses[0].probability = 1.5; },
                 "part 0 resting pose 0: probability is 1.5, expected in [0, 1]");
  expect_refused([](ModelBase& b) { b.parts[0].hull_vertices_mm[2].y() = -1e9; },
                 "part 0: hull vertex 2.y is -1e+09");
  expect_refused([](ModelBase& b) { b.views[0].moments[4] = INFINITY; }, "view 0: moment 5 is inf");
  expect_refused([](ModelBase& b) { b.views[1].cosmos.patches[0].centroid_mm.z() = -1e7; },
                 "view 1: patch 0 centroid_mm.z is -1e+07");
  expect_refused([](ModelBase& b) { b.clusters[2].centroid[0] = std::nan(""); },
                 "cluster 2: moment 1 is nan");
}

// A view's heights are bounded by its height coding's [low, high] (every decoded height is
// clamped into it): an absurd bound patched into the file's bytes behind a recomputed
// checksum is refused.
TEST_F(ModelBaseFile, AbsurdPointHeightBoundInTheFileIsRefused) {
  write_model_base(hand_made_base(), path_);
  std::string content = bytes();
  const ModelBase read = read_model_base(path_);
  // The height coding struct (step, low, high, ...; core/io/model_base.fbs) is found by its
  // bytes: a double and two integers no other place of the file repeats.
  const PackedRegistrationPoints& packed = read.views[3].registration_packed;
  const CoefficientCoding& height = packed.coefficients[kHeight];
  ASSERT_GT(height.step, 0.0);
  std::string coding(16, '\0');
  std::memcpy(coding.data(), &height.step, 8);
  std::memcpy(coding.data() + 8, &height.low, 4);
  std::memcpy(coding.data() + 12, &height.high, 4);
  const std::size_t step_at = content.find(coding);
  ASSERT_NE(step_at, std::string::npos);
  ASSERT_EQ(content.find(coding, step_at + 1), std::string::npos);
  const std::int32_t absurd = (1 << 28);
  std::memcpy(content.data() + step_at + 12, &absurd, 4);
  const std::uint64_t checksum =
      xxh64(content.data() + kModelBaseHeaderBytes, content.size() - kModelBaseHeaderBytes);
  for (int k = 0; k < 8; ++k)
    content[24 + static_cast<std::size_t>(k)] = static_cast<char>(checksum >> (8 * k));
  put_bytes(content);
  expect_refusal("view 3: registration height_mm upper bound is ");
  expect_refusal("expected within +-10000");
}

// A base of the previous format (24-byte points) is refused before anything is decoded, with
// the one line saying how to get a current one.
TEST_F(ModelBaseFile, AVersion1BaseIsRefusedWithTheWayToRebuildIt) {
  write_model_base(hand_made_base(), path_);
  std::string content = bytes();
  content[8] = 1;
  put_bytes(content);
  expect_refusal("format version 1, this build reads version " +
                 std::to_string(ModelBase::kFormatVersion) +
                 " (rebuild it with `cosmos modelbase build`)");
}

}  // namespace
}  // namespace cosmos
