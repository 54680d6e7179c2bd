// Range image files (core/io/range_image_file.hpp): bit-exact round trips through TIFF and
// PFM with their sidecar, and one-line InputErrors naming the file for every bad input.
#include "core/io/range_image_file.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include "core/input_error.hpp"
#include "sim/analytic_surface.hpp"
#include "tests/common/scratch_directory_test.hpp"
#include "tests/sim/handmade_image_files.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;
using testing::TiffSampleFormat;

class RangeImageFile : public testing::ScratchDirectoryTest {
 protected:
  // A small image whose values exercise sign, magnitude, subnormals and NaN positions.
  static RangeImage sample_image() {
    RangeImage image(7, 5, 0.25, 0.375);
    image.origin_x_mm = -12.125;
    image.origin_y_mm = 3.0 / 7.0;
    for (int row = 0; row < image.height(); ++row) {
      for (int column = 0; column < image.width(); ++column) {
        image.z_mm(column, row) =
            static_cast<float>(std::sin(column * 1.3 + row * 0.7) * 123.456 / 7.0);
      }
    }
    image.z_mm(0, 0) = std::numeric_limits<float>::quiet_NaN();
    image.z_mm(3, 2) = std::numeric_limits<float>::quiet_NaN();
    image.z_mm(6, 4) = std::numeric_limits<float>::quiet_NaN();
    image.z_mm(1, 0) = std::numeric_limits<float>::denorm_min();
    image.z_mm(2, 0) = -0.0f;
    return image;
  }

  static void write_sidecar(const fs::path& image_path, const std::string& yaml) {
    testing::write_text_file(sidecar_path(image_path), yaml);
  }

  // Asserts that reading `path` throws one InputError line containing every `needle`.
  static void expect_rejected(const fs::path& path, std::initializer_list<std::string> needles) {
    try {
      read_range_image(path);
      ADD_FAILURE() << path << " was accepted";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      for (const std::string& needle : needles) {
        EXPECT_NE(message.find(needle), std::string::npos)
            << "'" << needle << "' not in: " << message;
      }
    }
  }
};

void expect_bit_identical(const RangeImage& a, const RangeImage& b) {
  ASSERT_EQ(a.width(), b.width());
  ASSERT_EQ(a.height(), b.height());
  EXPECT_EQ(std::memcmp(a.z_mm.data(), b.z_mm.data(), a.z_mm.size() * sizeof(float)), 0);
  for (std::size_t i = 0; i < a.z_mm.size(); ++i)
    EXPECT_EQ(std::isnan(a.z_mm[i]), std::isnan(b.z_mm[i])) << i;
  EXPECT_EQ(a.pixel_size_x_mm, b.pixel_size_x_mm);
  EXPECT_EQ(a.pixel_size_y_mm, b.pixel_size_y_mm);
  EXPECT_EQ(a.origin_x_mm, b.origin_x_mm);
  EXPECT_EQ(a.origin_y_mm, b.origin_y_mm);
}

TEST_F(RangeImageFile, SidecarPathReplacesTheExtension) {
  EXPECT_EQ(sidecar_path("/a/b/scan.tiff"), fs::path("/a/b/scan.yaml"));
  EXPECT_EQ(sidecar_path("part.v2.pfm"), fs::path("part.v2.yaml"));
}

TEST_F(RangeImageFile, TiffRoundTripIsBitExactWithNaN) {
  const RangeImage image = sample_image();
  for (const char* name : {"scan.tiff", "scan.tif", "SCAN.TIF"}) {
    write_range_image(image, file(name));
    const RangeImage back = read_range_image(file(name));
    expect_bit_identical(image, back);
    EXPECT_FALSE(back.ground_truth.has_value());
    EXPECT_EQ(back.count_valid(), 32u);
  }
}

TEST_F(RangeImageFile, PfmRoundTripIsBitExactWithNaN) {
  const RangeImage image = sample_image();
  write_range_image(image, file("scan.pfm"));
  expect_bit_identical(image, read_range_image(file("scan.pfm")));
}

TEST_F(RangeImageFile, GroundTruthRoundTripsExactly) {
  RangeImage image = sample_image();
  GroundTruthPose pose;
  pose.part = "bracket-7";
  pose.rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  pose.translation_mm = Eigen::Vector3d(1.0 / 3.0, -250.125, 1e-7);
  image.ground_truth = pose;
  write_range_image(image, file("posed.tiff"));
  const RangeImage back = read_range_image(file("posed.tiff"));
  ASSERT_TRUE(back.ground_truth.has_value());
  EXPECT_EQ(back.ground_truth->part, "bracket-7");
  EXPECT_EQ(back.ground_truth->rotation, pose.rotation);
  EXPECT_EQ(back.ground_truth->translation_mm, pose.translation_mm);
}

TEST_F(RangeImageFile, AnalyticSurfaceRoundTripsThroughBothFormats) {
  AnalyticSurfaceSpec spec;
  spec.shape = AnalyticShape::kTorus;
  spec.noise_mm = 0.05;
  spec.rotate_deg = 17.0;
  const AnalyticSurface surface = make_analytic_surface(spec);
  for (const char* name : {"torus.tiff", "torus.pfm"}) {
    write_range_image(surface.range, file(name));
    const RangeImage back = read_range_image(file(name));
    expect_bit_identical(surface.range, back);
    ASSERT_TRUE(back.ground_truth.has_value());
    EXPECT_EQ(back.ground_truth->part, "torus");
    EXPECT_EQ(back.ground_truth->rotation, surface.range.ground_truth->rotation);
  }
}

TEST_F(RangeImageFile, HandWrittenSidecarIsRead) {
  write_range_image(sample_image(), file("hand.tiff"));
  write_sidecar(file("hand.tiff"),
                "# written by a person\npixel_size_mm: [0.2, 0.3]\nground_truth:\n  part: gear\n"
                "  rotation: [0, -1, 0, 1, 0, 0, 0, 0, 1]\n  translation_mm: [10, 20, 30]\n");
  const RangeImage back = read_range_image(file("hand.tiff"));
  EXPECT_EQ(back.pixel_size_x_mm, 0.2);
  EXPECT_EQ(back.pixel_size_y_mm, 0.3);
  EXPECT_EQ(back.origin_x_mm, 0.0);  // origin_mm is optional
  ASSERT_TRUE(back.ground_truth.has_value());
  EXPECT_EQ(back.ground_truth->rotation(0, 1), -1.0);
  EXPECT_EQ(back.ground_truth->translation_mm.z(), 30.0);
}

TEST_F(RangeImageFile, MissingImageIsRejected) {
  expect_rejected(file("absent.tiff"), {"absent.tiff", "no such file"});
}

TEST_F(RangeImageFile, UnknownExtensionIsRejected) {
  testing::write_text_file(file("photo.png"), "\x89PNG\r\n\x1a\n");
  expect_rejected(file("photo.png"), {"photo.png", "extension"});
  EXPECT_THROW(write_range_image(sample_image(), file("out.jpg")), InputError);
}

TEST_F(RangeImageFile, GarbageBytesAreUnreadable) {
  testing::write_text_file(file("garbage.tiff"), "this is not a TIFF at all");
  write_sidecar(file("garbage.tiff"), "pixel_size_mm: [1, 1]\n");
  expect_rejected(file("garbage.tiff"), {"garbage.tiff", "unreadable"});
  testing::write_text_file(file("empty.pfm"), "");
  expect_rejected(file("empty.pfm"), {"empty.pfm"});
}

TEST_F(RangeImageFile, AnotherFormatUnderTheExtensionIsRefusedBeforeDecoding) {
  // A DICOM preamble and a data element claiming a length of ~2 GB: decoded by its bytes
  // (OpenCV's DICOM decoder), it allocated gigabytes.
  const std::string dicom = std::string(128, 'x') + "DICM" +
                            std::string("\x32\x5d\x82\x32\x3f\x3f\x67\x7a\x6d\x3a\x71\x30", 12);
  for (const char* name : {"dicom.tiff", "dicom.pfm"}) {
    testing::write_text_file(file(name), dicom);
    write_sidecar(file(name), "pixel_size_mm: [1, 1]\n");
  }
  expect_rejected(file("dicom.tiff"), {"dicom.tiff", "not a TIFF file"});
  expect_rejected(file("dicom.pfm"), {"dicom.pfm", "not a PFM file"});
  // A PFM named .tiff is refused the same way.
  write_range_image(sample_image(), file("real.pfm"));
  fs::copy_file(file("real.pfm"), file("renamed.tiff"));
  write_sidecar(file("renamed.tiff"), "pixel_size_mm: [1, 1]\n");
  expect_rejected(file("renamed.tiff"), {"renamed.tiff", "not a TIFF file"});
}

TEST_F(RangeImageFile, HeaderClaimingTooManyPixelsIsRefusedBeforeDecoding) {
  // Decoded, a header declaring about a billion pixels made OpenCV allocate 4 GB before it
  // found the data missing.
  testing::write_text_file(file("huge.pfm"), "Pf\n32768 32683\n-1.0\n");
  write_sidecar(file("huge.pfm"), "pixel_size_mm: [1, 1]\n");
  expect_rejected(file("huge.pfm"), {"huge.pfm", "32768 x 32683", "more than"});
  testing::write_tiff_header_only(file("huge.tiff"), 40000, 30000, true, false);
  write_sidecar(file("huge.tiff"), "pixel_size_mm: [1, 1]\n");
  expect_rejected(file("huge.tiff"), {"huge.tiff", "40000 x 30000", "more than"});
  // At the limit itself the header passes; the missing data is what is reported.
  testing::write_tiff_header_only(file("edge.tiff"), 4096, 4096, false, false);
  write_sidecar(file("edge.tiff"), "pixel_size_mm: [1, 1]\n");
  expect_rejected(file("edge.tiff"), {"edge.tiff", "unreadable"});
}

TEST_F(RangeImageFile, ThreeChannelImagesAreRejected) {
  testing::write_handmade_tiff(file("rgb8.tiff"), 4, 3, 8, 3, TiffSampleFormat::kUnsigned);
  expect_rejected(file("rgb8.tiff"), {"rgb8.tiff", "3-channel"});
  testing::write_handmade_tiff(file("rgbf.tiff"), 4, 3, 32, 3, TiffSampleFormat::kFloat);
  expect_rejected(file("rgbf.tiff"), {"rgbf.tiff", "3-channel"});
  testing::write_handmade_pfm(file("rgb.pfm"), 4, 3, 3, 1.0f);
  expect_rejected(file("rgb.pfm"), {"rgb.pfm", "3-channel"});
}

TEST_F(RangeImageFile, NonFloat32DepthsAreRejected) {
  testing::write_handmade_tiff(file("gray8.tiff"), 4, 3, 8, 1, TiffSampleFormat::kUnsigned);
  expect_rejected(file("gray8.tiff"), {"gray8.tiff", "8-bit"});
  testing::write_handmade_tiff(file("gray16.tif"), 4, 3, 16, 1, TiffSampleFormat::kUnsigned);
  expect_rejected(file("gray16.tif"), {"gray16.tif", "16-bit"});
  testing::write_handmade_tiff(file("double.tiff"), 4, 3, 64, 1, TiffSampleFormat::kFloat);
  expect_rejected(file("double.tiff"), {"double.tiff"});
}

TEST_F(RangeImageFile, AllNaNIsRejected) {
  RangeImage image(6, 4, 0.5, 0.5);  // every pixel NaN
  write_range_image(image, file("blank.tiff"));
  expect_rejected(file("blank.tiff"), {"blank.tiff", "NaN"});
  write_range_image(image, file("blank.pfm"));
  expect_rejected(file("blank.pfm"), {"blank.pfm", "NaN"});
}

TEST_F(RangeImageFile, InfinityIsRejected) {
  RangeImage image = sample_image();
  image.z_mm(4, 3) = std::numeric_limits<float>::infinity();
  write_range_image(image, file("inf.tiff"));
  expect_rejected(file("inf.tiff"), {"inf.tiff", "infinite", "(4, 3)"});
  image.z_mm(4, 3) = -std::numeric_limits<float>::infinity();
  write_range_image(image, file("minus_inf.pfm"));
  expect_rejected(file("minus_inf.pfm"), {"minus_inf.pfm", "infinite"});
}

TEST_F(RangeImageFile, MissingSidecarIsRejected) {
  write_range_image(sample_image(), file("lonely.tiff"));
  fs::remove(sidecar_path(file("lonely.tiff")));
  expect_rejected(file("lonely.tiff"), {"lonely.tiff", "lonely.yaml", "sidecar"});
}

TEST_F(RangeImageFile, SidecarWithoutPixelSizeIsRejected) {
  write_range_image(sample_image(), file("nosize.tiff"));
  write_sidecar(file("nosize.tiff"), "origin_mm: [0, 0]\n");
  expect_rejected(file("nosize.tiff"), {"nosize.yaml", "pixel_size_mm", "missing"});
}

TEST_F(RangeImageFile, MalformedYamlIsRejectedWithItsLine) {
  write_range_image(sample_image(), file("broken.tiff"));
  write_sidecar(file("broken.tiff"), "origin_mm: [0, 0]\npixel_size_mm: [0.5, 0.5\nfoo: : :\n");
  expect_rejected(file("broken.tiff"), {"broken.yaml:", "malformed YAML"});
  write_sidecar(file("broken.tiff"), "just a scalar\n");
  expect_rejected(file("broken.tiff"), {"broken.yaml", "mapping"});
}

TEST_F(RangeImageFile, BadPixelSizesNameTheKeyAndLine) {
  write_range_image(sample_image(), file("bad.pfm"));
  write_sidecar(file("bad.pfm"), "origin_mm: [0, 0]\npixel_size_mm: [-0.5, 0.5]\n");
  expect_rejected(file("bad.pfm"), {"bad.yaml:2: pixel_size_mm:", "positive"});
  write_sidecar(file("bad.pfm"), "pixel_size_mm: [0, 0.5]\n");
  expect_rejected(file("bad.pfm"), {"bad.yaml:1: pixel_size_mm:", "positive"});
  write_sidecar(file("bad.pfm"), "pixel_size_mm: [0.5]\n");
  expect_rejected(file("bad.pfm"), {"bad.yaml:1: pixel_size_mm:", "2 numbers"});
  write_sidecar(file("bad.pfm"), "pixel_size_mm: 0.5\n");
  expect_rejected(file("bad.pfm"), {"bad.yaml:1: pixel_size_mm:", "list"});
  write_sidecar(file("bad.pfm"), "\n\npixel_size_mm: [0.5, wide]\n");
  expect_rejected(file("bad.pfm"), {"bad.yaml:3: pixel_size_mm:", "not a number"});
  write_sidecar(file("bad.pfm"), "pixel_size_mm: [0.5, .inf]\n");
  expect_rejected(file("bad.pfm"), {"bad.yaml:1: pixel_size_mm:", "not finite"});
}

TEST_F(RangeImageFile, BadGroundTruthIsRejected) {
  write_range_image(sample_image(), file("pose.tiff"));
  write_sidecar(file("pose.tiff"),
                "pixel_size_mm: [1, 1]\nground_truth:\n  part: gear\n  rotation: [1, 0, 0, 0, 1, "
                "0, 0, 0, -1]\n"
                "  translation_mm: [0, 0, 0]\n");
  expect_rejected(file("pose.tiff"), {"pose.yaml:4: ground_truth.rotation:", "rotation"});
  write_sidecar(file("pose.tiff"),
                "pixel_size_mm: [1, 1]\nground_truth:\n  part: gear\n"
                "  rotation: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n");
  expect_rejected(file("pose.tiff"), {"pose.yaml", "ground_truth.translation_mm", "missing"});
  write_sidecar(file("pose.tiff"), "pixel_size_mm: [1, 1]\nground_truth: 3\n");
  expect_rejected(file("pose.tiff"), {"pose.yaml:2: ground_truth:", "mapping"});
  write_sidecar(file("pose.tiff"), "pixel_size_mm: [1, 1]\norigin_mm: [1, 2, 3]\n");
  expect_rejected(file("pose.tiff"), {"pose.yaml:2: origin_mm:", "2 numbers"});
}

TEST_F(RangeImageFile, UnknownAndDuplicateSidecarKeysAreRejected) {
  write_range_image(sample_image(), file("keys.tiff"));
  // A typo of origin_mm used to be ignored: the image was read at origin (0, 0).
  write_sidecar(file("keys.tiff"), "pixel_size_mm: [1, 1]\norigin_nm: [5, 6]\n");
  expect_rejected(file("keys.tiff"), {"keys.yaml:2: origin_nm: unknown key", "origin_mm"});
  write_sidecar(file("keys.tiff"), "pixel_size_mm: [1, 1]\norigin_mm: [5, 6]\norigin_mm: [7, 8]\n");
  expect_rejected(file("keys.tiff"), {"keys.yaml:3: origin_mm: duplicate key"});
  write_sidecar(file("keys.tiff"),
                "pixel_size_mm: [1, 1]\nground_truth:\n  part: gear\n  part_name: gear\n"
                "  rotation: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n  translation_mm: [0, 0, 0]\n");
  expect_rejected(file("keys.tiff"), {"keys.yaml:4: ground_truth.part_name: unknown key"});
}

TEST_F(RangeImageFile, UnwritablePathIsReported) {
  try {
    write_range_image(sample_image(), file("no_such_dir") / "scan.tiff");
    ADD_FAILURE() << "write into a missing directory succeeded";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("scan.tiff"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace cosmos
