// The model base's FlatBuffers payload (core/io/model_base_payload.hpp), without the file
// around it: deterministic bytes within the size estimate, registration arrays decoded in
// place, and each invariant the decoder checks named in its refusal.
#include "core/io/model_base_payload.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/io/model_base_generated.h"
#include "core/modelbase/part_surface_summary.hpp"
#include "core/modelbase/view_signature.hpp"
#include "tests/core/hand_made_view.hpp"

namespace cosmos {
namespace {

// A tilted quadric patch with seeded noise: some dozens of registration points.
RegistrationPoints registration_points(double tilt) {
  RangeImage image(24, 20, 0.4, 0.4);
  std::mt19937 generator(5);
  std::normal_distribution<float> noise(0.0f, 0.02f);
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column) {
      const double x = image.x_mm(column), y = image.y_mm(row);
      image.z_mm(column, row) =
          static_cast<float>(30 + tilt * x + 0.01 * x * x + 0.004 * y * y) + noise(generator);
    }
  RegistrationPointParameters parameters;
  parameters.stride_px = 2;
  return build_registration_points(image, parameters).points;
}

// Parts "cow" (views 0, 1) and "spool" (view 2), a cluster per part.
ModelBase small_base() {
  ModelBase base;
  base.catalog_hash = "feedc0ffee";
  base.parameters_text = "{\"cosmos\":{\"fit\":{\"window_size\":5}}}";
  base.parts = {{"cow", "cow.off", 120, 131.5, false, {}, {}, {}, {}, {}},
                {"spool", "spool.off", 70, 74.25, true, {}, {}, {}, {}, {}}};
  base.parts[0].resting_poses = {{rotation_from_xyz_angles_deg(180, 0, 0), 21.5, 0.625},
                                 {rotation_from_xyz_angles_deg(90, 0, 0), 30.25, 0.375}};
  base.parts[0].hull_vertices_mm = {{-60, -20, -21.5}, {60, 25, 30}, {0, -30, 5}};
  base.parts[1].confusable_parts = {0};
  for (int k = 0; k < 3; ++k) {
    ModelBaseView view;
    view.part_index = k < 2 ? 0 : 1;
    view.view_index = 4 * k + 3;
    view.direction_part = Eigen::Vector3d(0.2 * k, 0.1, 1.0).normalized();
    view.T_scanner_part.rotation = rotation_from_xyz_angles_deg(5.0 * k, 10.0, -20.0);
    view.T_scanner_part.translation_mm = {k * 1.5, 2.0, 40.0};
    view.cosmos = testing::hand_made_view_analysis().view;
    for (std::size_t m = 0; m < view.moments.size(); ++m) view.moments[m] = 0.1 * k + 1e-3 * m;
    view.registration = registration_points(0.1 * k);
    if (k > 0) view.extent = {30.5 + k, 95.25, 60.125};
    base.views.push_back(std::move(view));
  }
  base.clusters = {{0, {0, 1}, {}}, {1, {2}, {}}};
  base.clusters[0].centroid.fill(0.125);
  base.clusters[1].centroid.fill(0.5);
  summarize_part_surfaces(base, {});
  for (int part = 0; part < 2; ++part) summarize_view_signatures(base, part);
  return base;
}

std::vector<std::uint8_t> encode(const ModelBase& base) {
  flatbuffers::FlatBufferBuilder builder(estimated_payload_bytes(base));
  encode_model_base(base, builder);
  return {builder.GetBufferPointer(), builder.GetBufferPointer() + builder.GetSize()};
}

// Decodes a copy in a block aligned like the file reader's (operator new: 16 bytes).
struct Decoded {
  std::shared_ptr<std::uint8_t[]> payload;
  std::size_t bytes = 0;
  ModelBase base;
  std::optional<std::string> refusal;
};
Decoded decode(const std::vector<std::uint8_t>& bytes) {
  Decoded out;
  out.bytes = bytes.size();
  out.payload =
      std::shared_ptr<std::uint8_t[]>(new std::uint8_t[std::max<std::size_t>(1, bytes.size())]);
  std::memcpy(out.payload.get(), bytes.data(), bytes.size());
  out.refusal = decode_model_base(out.payload.get(), out.bytes, out.payload, out.base);
  return out;
}

TEST(ModelBasePayload, EncodingIsDeterministicAndWithinTheEstimate) {
  const ModelBase base = small_base();
  const std::vector<std::uint8_t> bytes = encode(base);
  EXPECT_EQ(encode(base), bytes);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(bytes.data()) + 4, 4), "CSMB");
  EXPECT_GE(estimated_payload_bytes(base), bytes.size());
  // A decoded base holds the packed form only: its estimate still bounds its bytes.
  const Decoded decoded = decode(bytes);
  ASSERT_FALSE(decoded.refusal) << *decoded.refusal;
  EXPECT_GE(estimated_payload_bytes(decoded.base), encode(decoded.base).size());
}

TEST(ModelBasePayload, DecodesWhatWasEncoded) {
  const ModelBase base = small_base();
  const Decoded decoded = decode(encode(base));
  ASSERT_FALSE(decoded.refusal) << *decoded.refusal;
  const ModelBase& read = decoded.base;
  EXPECT_EQ(read.catalog_hash, base.catalog_hash);
  EXPECT_EQ(read.parameters_text, base.parameters_text);
  ASSERT_EQ(read.parts.size(), 2u);
  EXPECT_EQ(read.parts[1].name, "spool");
  EXPECT_EQ(read.parts[1].diameter_mm, 74.25);
  EXPECT_TRUE(read.parts[1].symmetric);
  EXPECT_TRUE(read.parts[1].resting_poses.empty());
  ASSERT_EQ(read.parts[0].resting_poses.size(), 2u);
  EXPECT_EQ(read.parts[0].resting_poses[1].R_belt_part, base.parts[0].resting_poses[1].R_belt_part);
  EXPECT_EQ(read.parts[0].resting_poses[1].height_mm, 30.25);
  EXPECT_EQ(read.parts[0].resting_poses[0].probability, 0.625);
  EXPECT_EQ(read.parts[0].hull_vertices_mm, base.parts[0].hull_vertices_mm);
  EXPECT_TRUE(read.parts[0].confusable_parts.empty());
  EXPECT_EQ(read.parts[1].confusable_parts, std::vector<int>{0});
  ASSERT_EQ(read.views.size(), 3u);
  const ModelBaseView &view = read.views[2], &written = base.views[2];
  EXPECT_EQ(view.part_index, 1);
  EXPECT_EQ(view.view_index, 11);
  EXPECT_EQ(view.direction_part, written.direction_part);
  EXPECT_EQ(view.T_scanner_part.rotation, written.T_scanner_part.rotation);
  EXPECT_EQ(view.T_scanner_part.translation_mm, written.T_scanner_part.translation_mm);
  EXPECT_EQ(view.moments, written.moments);
  EXPECT_EQ(view.extent.highest_mm, 32.5);
  EXPECT_EQ(view.extent.widest_mm, 95.25);
  EXPECT_EQ(view.extent.narrowest_mm, 60.125);
  EXPECT_TRUE(std::isinf(read.views[0].extent.highest_mm));  // unbounded, kept so
  EXPECT_TRUE(std::isinf(read.views[0].extent.narrowest_mm));
  EXPECT_FALSE(view.signature.empty());
  EXPECT_EQ(view.signature.cumulative, written.signature.cumulative);
  ASSERT_EQ(view.cosmos.patches.size(), 4u);
  EXPECT_EQ(view.cosmos.patches[1].mean_normal, written.cosmos.patches[1].mean_normal);
  ASSERT_EQ(view.cosmos.patches[1].neighbors.size(), 3u);
  EXPECT_EQ(view.cosmos.patches[1].neighbors[2].patch, 3);
  EXPECT_EQ(view.cosmos.gauss_map.size(), written.cosmos.gauss_map.size());
  EXPECT_EQ(view.registration_packed.size(), written.registration.size());
  EXPECT_EQ(view.control_point_centroid_mm, written.control_point_centroid_mm);
  const PartSurfaceVoxels &voxels = read.parts[0].surface_voxels,
                          &written_voxels = base.parts[0].surface_voxels;
  EXPECT_GT(voxels.occupied_voxels, 0u);
  EXPECT_EQ(voxels.occupied_voxels, written_voxels.occupied_voxels);
  EXPECT_EQ(voxels.occupied_runs, written_voxels.occupied_runs);
  EXPECT_EQ(voxels.size, written_voxels.size);
  EXPECT_EQ(voxels.origin_mm, written_voxels.origin_mm);
  EXPECT_EQ(voxels.voxel_mm, written_voxels.voxel_mm);
  EXPECT_FALSE(read.parts[0].surface_sample_mm.empty());
  EXPECT_EQ(read.parts[0].surface_sample_mm, base.parts[0].surface_sample_mm);
  ASSERT_EQ(read.clusters.size(), 2u);
  EXPECT_EQ(read.clusters[0].views, (std::vector<int>{0, 1}));
  EXPECT_EQ(read.clusters[1].centroid, base.clusters[1].centroid);
}

TEST(ModelBasePayload, RegistrationStreamsAreReadInPlace) {
  const Decoded decoded = decode(encode(small_base()));
  ASSERT_FALSE(decoded.refusal) << *decoded.refusal;
  const auto inside = [&](const void* p) {
    const auto* byte = static_cast<const std::uint8_t*>(p);
    return byte >= decoded.payload.get() && byte < decoded.payload.get() + decoded.bytes;
  };
  for (const ModelBaseView& view : decoded.base.views) {
    const PackedRegistrationPoints& packed = view.registration_packed;
    ASSERT_GT(packed.size(), 20);
    EXPECT_TRUE(inside(packed.coefficient_bits.data()));
    EXPECT_TRUE(inside(packed.occupancy_runs.data()));
    EXPECT_EQ(packed.storage.get(), decoded.payload.get());  // keeps the payload alive
    EXPECT_EQ(view.registration.size(), 0);                  // only the packed form
  }
}

// The refusal of a base encoded after `damage`.
std::string refusal_after(void (*damage)(ModelBase&)) {
  ModelBase base = small_base();
  damage(base);
  const Decoded decoded = decode(encode(base));
  return decoded.refusal.value_or("accepted");
}

// The verifier checks a vector's length word's alignment, not its elements': a crafted payload
// may put a part's resting poses and hull corners (doubles) off their 8 bytes, and they are
// read as written wherever they lie (a fuzzing finding, caught by UBSan in
// scripts/check_sanitizers.sh).
TEST(ModelBasePayload, StructVectorsOffTheirElementsAlignmentAreReadAsWritten) {
  int misaligned = 0;
  for (int padding_words = 0; padding_words < 2; ++padding_words) {
    flatbuffers::FlatBufferBuilder b;
    const fb::Vec3 corner(1.5, -2.25, 3.0);
    const fb::RestingPose pose(
        fb::Transform(fb::Vec3(1, 0, 0), fb::Vec3(0, 1, 0), fb::Vec3(0, 0, 1), fb::Vec3(0, 0, 7.5)),
        0.875);
    for (int k = 0; k < padding_words; ++k) b.PushElement<std::uint32_t>(0);
    b.StartVector(1, sizeof(std::uint32_t));
    b.PushBytes(reinterpret_cast<const std::uint8_t*>(&corner), sizeof corner);
    const flatbuffers::Offset<flatbuffers::Vector<const fb::Vec3*>> hull(b.EndVector(1));
    for (int k = 0; k < padding_words; ++k) b.PushElement<std::uint32_t>(0);
    b.StartVector(1, sizeof(std::uint32_t));
    b.PushBytes(reinterpret_cast<const std::uint8_t*>(&pose), sizeof pose);
    const flatbuffers::Offset<flatbuffers::Vector<const fb::RestingPose*>> resting(b.EndVector(1));
    const auto no_voxels = fb::CreateSurfaceVoxels(b);
    const auto part = fb::CreatePart(b, b.CreateString("cow"), b.CreateString("cow.off"), 120,
                                     131.5, false, resting, hull, no_voxels);
    const auto parts = b.CreateVector(std::vector<flatbuffers::Offset<fb::Part>>{part});
    fb::FinishModelBaseBuffer(
        b, fb::CreateModelBase(b, ModelBase::kFormatVersion, b.CreateString("feedc0ffee"),
                               b.CreateString("{}"), parts));
    const Decoded decoded = decode({b.GetBufferPointer(), b.GetBufferPointer() + b.GetSize()});
    ASSERT_FALSE(decoded.refusal) << *decoded.refusal;
    const fb::Part& written = *fb::GetModelBase(decoded.payload.get())->parts()->Get(0);
    misaligned += reinterpret_cast<std::uintptr_t>(written.hull_vertices_mm()->Data()) % 8 != 0;
    misaligned += reinterpret_cast<std::uintptr_t>(written.resting_poses()->Data()) % 8 != 0;
    ASSERT_EQ(decoded.base.parts.size(), 1u);
    const ModelPart& read = decoded.base.parts[0];
    ASSERT_EQ(read.hull_vertices_mm.size(), 1u);
    EXPECT_EQ(read.hull_vertices_mm[0], Eigen::Vector3d(1.5, -2.25, 3.0));
    ASSERT_EQ(read.resting_poses.size(), 1u);
    EXPECT_EQ(read.resting_poses[0].height_mm, 7.5);
    EXPECT_EQ(read.resting_poses[0].probability, 0.875);
    EXPECT_TRUE(read.resting_poses[0].R_belt_part.isIdentity(0));
  }
  // The paddings put the vectors' elements off 8 bytes at least once.
  EXPECT_GE(misaligned, 1);
}

TEST(ModelBasePayload, IndicesOutOfTheirRangeAreRefusedNamingWhere) {
  EXPECT_EQ(refusal_after([](ModelBase& b) { b.views[1].part_index = 2; }),
            "view 1: part index 2 out of range");
  EXPECT_EQ(refusal_after([](ModelBase& b) { b.clusters[1].part_index = -1; }),
            "cluster 1: part index -1 out of range");
  EXPECT_EQ(refusal_after([](ModelBase& b) {
              b.clusters[0].views = {0, 3};
            }),
            "cluster 0: view 3 out of range");
  EXPECT_EQ(refusal_after([](ModelBase& b) {
              b.clusters[1].views = {2, 0};
            }),
            "cluster 1: view 0 belongs to another part");
  EXPECT_EQ(refusal_after([](ModelBase& b) {
              b.parts[0].confusable_parts = {1, 2};
            }),
            "part 0: confusable part 2 out of range");
}

TEST(ModelBasePayload, SurfaceVoxelsThatDoNotCoverTheirGridAreRefusedNamingThePart) {
  const std::string more_than_the_runs =
      refusal_after([](ModelBase& b) { ++b.parts[1].surface_voxels.occupied_voxels; });
  EXPECT_EQ(more_than_the_runs.rfind("part 1: surface voxels do not match their grid (", 0), 0u)
      << more_than_the_runs;
  const std::string a_grid_too_large = refusal_after([](ModelBase& b) {
    b.parts[0].surface_voxels.size = {1 << 12, 1 << 12, 2};
  });
  EXPECT_EQ(
      a_grid_too_large.rfind("part 0: surface voxels do not match their grid (4096 x 4096 x 2", 0),
      0u)
      << a_grid_too_large;
  EXPECT_EQ(refusal_after([](ModelBase& b) { b.parts[0].surface_sample_mm[3].y() = 1e300; }),
            "part 0: surface sample point 3.y is 1e+300, expected within +-10000");
  EXPECT_EQ(refusal_after([](ModelBase& b) { b.views[1].extent.widest_mm = -4; }),
            "view 1: extent.widest_mm is -4, expected in [0, 10000]");
  EXPECT_EQ(refusal_after([](ModelBase& b) {
              b.views[2].extent.highest_mm = std::numeric_limits<double>::quiet_NaN();
            }),
            "view 2: extent.highest_mm is nan, expected in [0, 10000]");
  EXPECT_EQ(refusal_after([](ModelBase& b) {
              b.views[1].signature.cumulative[ViewSignature::kHeightBins - 1] = 100;
            }),
            "view 1: signature is not three cumulative distributions, each ending at 65535");
}

TEST(ModelBasePayload, BytesThatAreNotAPayloadAreRefused) {
  EXPECT_EQ(decode(std::vector<std::uint8_t>(64, 0)).refusal, "no CSMB payload identifier");
  std::vector<std::uint8_t> truncated = encode(small_base());
  truncated.resize(truncated.size() / 2);  // the identifier survives, the tables do not
  EXPECT_EQ(decode(truncated).refusal, "FlatBuffers verifier rejects the payload");
}

}  // namespace
}  // namespace cosmos
