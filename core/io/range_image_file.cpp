#include "core/io/range_image_file.hpp"

#include <yaml-cpp/yaml.h>

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "core/input_error.hpp"
#include "core/io/image_header.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// The message contract is one line: a file name or a parser message with a line break in
// it must not split the report the CLI prints.
[[noreturn]] void fail(const std::string& where, const std::string& reason) {
  std::string message = where + ": " + reason;
  std::replace_if(
      message.begin(), message.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  throw InputError(message);
}

[[noreturn]] void fail(const fs::path& file, const std::string& reason) {
  fail(file.string(), reason);
}

// A sidecar problem: "file.yaml:LINE: key: reason" when yaml-cpp knows where the node is.
[[noreturn]] void fail_key(const fs::path& sidecar, const YAML::Node& node, const std::string& key,
                           const std::string& reason) {
  std::string where = sidecar.string();
  if (node.IsDefined()) {
    const YAML::Mark mark = node.Mark();
    if (!mark.is_null()) where += ":" + std::to_string(mark.line + 1);
  }
  fail(where, key + ": " + reason);
}

enum class ImageFormat { kTiff, kPfm };

ImageFormat format_of(const fs::path& image_path) {
  std::string extension = image_path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".tif" || extension == ".tiff") return ImageFormat::kTiff;
  if (extension == ".pfm") return ImageFormat::kPfm;
  fail(image_path,
       "unknown range image extension '" + extension + "' (expected .tif, .tiff or .pfm)");
}

// OpenCV reports a decoder's failure on its own before the reader can: its logger, its error
// callback, and imread's own lines on std::cerr ("imread_('...'): can't read header: ...").
// The reader reports every failure itself as one InputError line, so all three are silenced
// for the duration of a call.
int ignore_opencv_error(int, const char*, const char*, const char*, int, void*) { return 0; }

class QuietOpenCv {
 public:
  QuietOpenCv()
      : previous_level_(cv::utils::logging::getLogLevel()),
        previous_handler_(cv::redirectError(ignore_opencv_error, nullptr, &previous_data_)),
        previous_cerr_(std::cerr.rdbuf(&discard_)) {
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  }
  ~QuietOpenCv() {
    std::cerr.rdbuf(previous_cerr_);
    cv::redirectError(previous_handler_, previous_data_);
    cv::utils::logging::setLogLevel(previous_level_);
  }
  QuietOpenCv(const QuietOpenCv&) = delete;
  QuietOpenCv& operator=(const QuietOpenCv&) = delete;

 private:
  // A stream buffer that drops whatever is written to it.
  struct Discard : std::streambuf {
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
  };

  Discard discard_;
  cv::utils::logging::LogLevel previous_level_;
  void* previous_data_ = nullptr;
  cv::ErrorCallback previous_handler_;
  std::streambuf* previous_cerr_;
};

std::string depth_name(int depth) {
  switch (depth) {
    case CV_8U:
      return "8-bit unsigned";
    case CV_8S:
      return "8-bit signed";
    case CV_16U:
      return "16-bit unsigned";
    case CV_16S:
      return "16-bit signed";
    case CV_32S:
      return "32-bit integer";
    case CV_64F:
      return "64-bit float";
    default:
      return "non-float32";
  }
}

// OpenCV picks its decoder from the file's first bytes, not its name: a file named .tiff that
// holds another format (DICOM, JPEG 2000, ...) would go to that format's decoder, which the
// reader never means to run on input (a few crafted bytes of DICOM allocate gigabytes). So
// the file must start as its extension's format does: "II*\0" or "MM\0*" (TIFF; '+' for
// BigTIFF), "Pf" or "PF" and a line break (PFM).
bool has_signature_of(ImageFormat format, std::ifstream& file) {
  std::array<char, 4> head{};
  file.read(head.data(), head.size());
  if (file.gcount() < 3) return false;
  if (format == ImageFormat::kPfm)
    return head[0] == 'P' && (head[1] == 'f' || head[1] == 'F') &&
           std::isspace(static_cast<unsigned char>(head[2]));
  if (file.gcount() < 4) return false;
  const bool little =
      head[0] == 'I' && head[1] == 'I' && (head[2] == '*' || head[2] == '+') && head[3] == '\0';
  const bool big =
      head[0] == 'M' && head[1] == 'M' && head[2] == '\0' && (head[3] == '*' || head[3] == '+');
  return little || big;
}

// A decoder allocates what the header claims before it finds the data missing: a few crafted
// bytes declaring a billion pixels took gigabytes. The reader refuses such a header itself.
void check_declared_size(ImageFormat format, const fs::path& image_path) {
  const std::optional<ImageDimensions> declared = format == ImageFormat::kTiff
                                                      ? read_tiff_dimensions(image_path)
                                                      : read_pfm_dimensions(image_path);
  if (declared && declared->pixels() > kMaxRangeImagePixels) {
    fail(image_path, "declares " + std::to_string(declared->width) + " x " +
                         std::to_string(declared->height) +
                         " pixels, more than a range image may have (" +
                         std::to_string(kMaxRangeImagePixels) + ")");
  }
}

cv::Mat load_image(const fs::path& image_path) {
  std::error_code error;
  if (!fs::exists(image_path, error)) fail(image_path, "no such file");
  if (!fs::is_regular_file(image_path, error)) fail(image_path, "not a regular file");
  std::ifstream file(image_path, std::ios::binary);
  if (!file) fail(image_path, "cannot be opened for reading");
  const ImageFormat format = format_of(image_path);
  if (!has_signature_of(format, file))
    fail(image_path, std::string("unreadable: not a ") +
                         (format == ImageFormat::kTiff ? "TIFF" : "PFM") +
                         " file (its first bytes are not that format's header)");
  check_declared_size(format, image_path);
  cv::Mat image;
  try {
    QuietOpenCv quiet;
    image = cv::imread(image_path.string(), cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {
    fail(image_path, "unreadable: not a valid image of its format");
  }
  if (image.empty()) fail(image_path, "unreadable: not a valid image of its format");
  return image;
}

PixelGrid<float> to_depth_grid(const cv::Mat& image, const fs::path& image_path) {
  if (image.channels() != 1) {
    fail(image_path, std::to_string(image.channels()) +
                         "-channel image; a range image has a single float32 channel");
  }
  if (image.depth() != CV_32F) {
    fail(image_path, depth_name(image.depth()) + " image; a range image is float32 (z in mm)");
  }
  PixelGrid<float> z_mm(image.cols, image.rows);
  bool any_finite = false;
  for (int row = 0; row < image.rows; ++row) {
    const float* source = image.ptr<float>(row);
    std::memcpy(z_mm.row(row), source, sizeof(float) * static_cast<std::size_t>(image.cols));
    for (int column = 0; column < image.cols; ++column) {
      if (std::isinf(source[column])) {
        fail(image_path, "infinite depth at pixel (" + std::to_string(column) + ", " +
                             std::to_string(row) + "); no-data pixels must be NaN");
      }
      any_finite = any_finite || std::isfinite(source[column]);
    }
  }
  if (!any_finite) fail(image_path, "every pixel is NaN (no range data)");
  return z_mm;
}

// Every key of `map` is one of `known`, once: a misspelt key would otherwise be ignored and
// its default used (an origin of (0, 0) for a typo of origin_mm).
void check_keys(const fs::path& sidecar, const YAML::Node& map, const std::string& prefix,
                std::initializer_list<const char*> known) {
  std::vector<std::string> seen;
  for (const auto& entry : map) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : std::string("?");
    const std::string dotted = prefix.empty() ? key : prefix + "." + key;
    if (std::find(seen.begin(), seen.end(), key) != seen.end())
      fail_key(sidecar, entry.first, dotted, "duplicate key");
    seen.push_back(key);
    if (std::none_of(known.begin(), known.end(), [&key](const char* k) { return key == k; })) {
      std::string expected;
      for (const char* k : known) expected.append(expected.empty() ? "" : ", ").append(k);
      fail_key(sidecar, entry.first, dotted, "unknown key (expected " + expected + ")");
    }
  }
}

// Reads a YAML sequence of exactly N finite numbers.
template <std::size_t N>
std::array<double, N> read_numbers(const fs::path& sidecar, const YAML::Node& node,
                                   const std::string& key) {
  const std::string expected = "expected a list of " + std::to_string(N) + " numbers";
  if (!node.IsSequence()) fail_key(sidecar, node, key, expected);
  if (node.size() != N) {
    fail_key(sidecar, node, key, expected + ", got " + std::to_string(node.size()));
  }
  std::array<double, N> values{};
  for (std::size_t i = 0; i < N; ++i) {
    const YAML::Node element = node[i];
    if (!element.IsScalar() || !YAML::convert<double>::decode(element, values[i])) {
      fail_key(sidecar, element, key, "element " + std::to_string(i) + " is not a number");
    }
    if (!std::isfinite(values[i])) {
      fail_key(sidecar, element, key, "element " + std::to_string(i) + " is not finite");
    }
  }
  return values;
}

GroundTruthPose read_ground_truth(const fs::path& sidecar, const YAML::Node& node) {
  if (!node.IsMap()) fail_key(sidecar, node, "ground_truth", "expected a mapping");
  check_keys(sidecar, node, "ground_truth", {"part", "rotation", "translation_mm"});
  GroundTruthPose pose;
  const YAML::Node part = node["part"];
  if (!part.IsDefined()) fail_key(sidecar, node, "ground_truth.part", "missing");
  if (!part.IsScalar()) fail_key(sidecar, part, "ground_truth.part", "expected a name");
  pose.part = part.Scalar();

  const YAML::Node rotation = node["rotation"];
  if (!rotation.IsDefined()) fail_key(sidecar, node, "ground_truth.rotation", "missing");
  const auto r = read_numbers<9>(sidecar, rotation, "ground_truth.rotation");
  for (int i = 0; i < 9; ++i) pose.rotation(i / 3, i % 3) = r[static_cast<std::size_t>(i)];
  // Hand-written sidecars carry rounded values (0.7071), hence the loose tolerance; a
  // reflection or a non-orthonormal matrix would silently corrupt every pose evaluation.
  const double orthonormality_error =
      (pose.rotation.transpose() * pose.rotation - Eigen::Matrix3d::Identity())
          .cwiseAbs()
          .maxCoeff();
  if (orthonormality_error > 1e-3 || pose.rotation.determinant() <= 0.0) {
    fail_key(sidecar, rotation, "ground_truth.rotation", "not a rotation matrix (row-major 3x3)");
  }

  const YAML::Node translation = node["translation_mm"];
  if (!translation.IsDefined()) fail_key(sidecar, node, "ground_truth.translation_mm", "missing");
  const auto t = read_numbers<3>(sidecar, translation, "ground_truth.translation_mm");
  pose.translation_mm = Eigen::Vector3d(t[0], t[1], t[2]);
  return pose;
}

// Fills the pixel size, origin and ground truth of `image` from its sidecar.
void read_sidecar(const fs::path& image_path, RangeImage& image) {
  const fs::path sidecar = sidecar_path(image_path);
  std::error_code error;
  if (!fs::exists(sidecar, error)) {
    fail(image_path, "missing sidecar " + sidecar.string() + " (it holds pixel_size_mm)");
  }
  if (!std::ifstream(sidecar)) fail(sidecar, "cannot be opened for reading");
  YAML::Node root;
  try {
    root = YAML::LoadFile(sidecar.string());
  } catch (const YAML::Exception& exception) {
    const std::string where =
        exception.mark.is_null() ? sidecar.string()
                                 : sidecar.string() + ":" + std::to_string(exception.mark.line + 1);
    fail(where, "malformed YAML: " + exception.msg);
  }
  if (!root.IsMap()) fail(sidecar, "expected a YAML mapping with pixel_size_mm: [dx, dy]");
  check_keys(sidecar, root, "", {"pixel_size_mm", "origin_mm", "ground_truth"});

  const YAML::Node pixel_size = root["pixel_size_mm"];
  if (!pixel_size.IsDefined()) fail(sidecar, "pixel_size_mm: missing (required, [dx, dy] in mm)");
  const auto size_mm = read_numbers<2>(sidecar, pixel_size, "pixel_size_mm");
  if (size_mm[0] <= 0.0 || size_mm[1] <= 0.0) {
    fail_key(sidecar, pixel_size, "pixel_size_mm", "both values must be positive");
  }
  image.pixel_size_x_mm = size_mm[0];
  image.pixel_size_y_mm = size_mm[1];

  if (const YAML::Node origin = root["origin_mm"]; origin.IsDefined()) {
    const auto origin_mm = read_numbers<2>(sidecar, origin, "origin_mm");
    image.origin_x_mm = origin_mm[0];
    image.origin_y_mm = origin_mm[1];
  }
  if (const YAML::Node truth = root["ground_truth"]; truth.IsDefined()) {
    image.ground_truth = read_ground_truth(sidecar, truth);
  }
}

void write_sidecar(const RangeImage& image, const fs::path& image_path) {
  YAML::Emitter out;
  // 17 significant digits make every double read back bit-identical.
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "pixel_size_mm" << YAML::Value << YAML::Flow << YAML::BeginSeq
      << image.pixel_size_x_mm << image.pixel_size_y_mm << YAML::EndSeq;
  out << YAML::Key << "origin_mm" << YAML::Value << YAML::Flow << YAML::BeginSeq
      << image.origin_x_mm << image.origin_y_mm << YAML::EndSeq;
  if (image.ground_truth) {
    const GroundTruthPose& pose = *image.ground_truth;
    out << YAML::Key << "ground_truth" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "part" << YAML::Value << pose.part;
    out << YAML::Key << "rotation" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (int i = 0; i < 9; ++i) out << pose.rotation(i / 3, i % 3);
    out << YAML::EndSeq;
    out << YAML::Key << "translation_mm" << YAML::Value << YAML::Flow << YAML::BeginSeq
        << pose.translation_mm.x() << pose.translation_mm.y() << pose.translation_mm.z()
        << YAML::EndSeq;
    out << YAML::EndMap;
  }
  out << YAML::EndMap;

  const fs::path sidecar = sidecar_path(image_path);
  std::ofstream file(sidecar);
  file << out.c_str() << "\n";
  if (!file) fail(sidecar, "cannot be written");
}

}  // namespace

std::filesystem::path sidecar_path(const std::filesystem::path& image_path) {
  return std::filesystem::path(image_path).replace_extension(".yaml");
}

RangeImage read_range_image(const std::filesystem::path& image_path) {
  format_of(image_path);
  RangeImage image;
  image.z_mm = to_depth_grid(load_image(image_path), image_path);
  read_sidecar(image_path, image);
  return image;
}

void write_range_image(const RangeImage& image, const std::filesystem::path& image_path) {
  format_of(image_path);
  if (image.width() <= 0 || image.height() <= 0)
    fail(image_path, "cannot write an empty range image");
  if (!(image.pixel_size_x_mm > 0.0) || !(image.pixel_size_y_mm > 0.0)) {
    fail(image_path, "cannot write a range image without a positive pixel size");
  }
  // libtiff prints its own open failures to stderr; probing the path first keeps the report
  // to the one InputError line.
  const fs::path parent = image_path.has_parent_path() ? image_path.parent_path() : fs::path(".");
  std::error_code error;
  if (!fs::is_directory(parent, error))
    fail(image_path, "cannot be written: no directory " + parent.string());
  if (!std::ofstream(image_path, std::ios::binary))
    fail(image_path, "cannot be opened for writing");
  // cv::imwrite only reads the pixels; the const_cast lets a cv::Mat header view them in place.
  const cv::Mat view(image.height(), image.width(), CV_32FC1,
                     const_cast<float*>(image.z_mm.data()));
  bool written = false;
  try {
    QuietOpenCv quiet;
    written = cv::imwrite(image_path.string(), view);
  } catch (const cv::Exception&) {
    written = false;
  }
  if (!written) fail(image_path, "cannot be written");
  write_sidecar(image, image_path);
}

}  // namespace cosmos
