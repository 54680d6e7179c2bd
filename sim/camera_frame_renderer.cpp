#include "sim/camera_frame_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "firmware_bridge/profile_resampling.hpp"
#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

constexpr int kPhases = 256;                 // sub-pixel phases of the stripe tap table
constexpr std::size_t kPoolSize = 1u << 17;  // pre-drawn normal deviates
constexpr std::uint64_t kBackgroundStream = 0xB4C6;
constexpr std::uint64_t kPoolStream = 0x9001;

bool drawable(LaserSampleState state) {
  // Dark samples are drawn too: whether their weak stripe is found is the extractor's call.
  return state == LaserSampleState::kMeasured || state == LaserSampleState::kDark;
}

template <class Pixel>
void add_to_pixel(cv::Mat& frame, int row, int column, double value, int full_scale) {
  Pixel& pixel = frame.ptr<Pixel>(row)[column];
  const double sum = std::round(pixel + value);
  pixel = static_cast<Pixel>(std::clamp(sum, 0.0, static_cast<double>(full_scale)));
}

}  // namespace

CameraFrameRenderer::CameraFrameRenderer(const ScannerParameters& parameters,
                                         const TriangulationGeometry& geometry)
    : parameters_(parameters), geometry_(geometry) {
  const CameraFrameParameters& camera = parameters.camera;
  if (camera.bit_depth != 8 && camera.bit_depth != 10 && camera.bit_depth != 12 &&
      camera.bit_depth != 16) {
    throw std::invalid_argument("CameraFrameRenderer: bit_depth must be 8, 10, 12 or 16");
  }
  full_scale_ = (1 << camera.bit_depth) - 1;
  rows_ = geometry.roi_height_px;
  columns_ = geometry.camera.width_px;
  max_z_jump_mm_ = ProfileResamplingParameters{}.max_z_jump_mm;

  half_taps_ = static_cast<int>(std::ceil(3.5 * camera.stripe_sigma_px));
  const int taps = 2 * half_taps_ + 2;
  taps_.resize(static_cast<std::size_t>(kPhases * taps));
  for (int phase = 0; phase < kPhases; ++phase) {
    const double fraction = (phase + 0.5) / kPhases;
    for (int tap = 0; tap < taps; ++tap) {
      const double offset = (tap - half_taps_) - fraction;
      taps_[static_cast<std::size_t>(phase * taps + tap)] = static_cast<float>(
          std::exp(-0.5 * offset * offset / (camera.stripe_sigma_px * camera.stripe_sigma_px)));
    }
  }

  SeededRandom pool_random(mix_seed(parameters.seed, kPoolStream));
  normal_pool_.resize(kPoolSize);
  for (float& value : normal_pool_) value = static_cast<float>(pool_random.normal());

  SeededRandom background_random(mix_seed(parameters.seed, kBackgroundStream));
  const double ambient = camera.ambient_level * full_scale_;
  const double read_noise = camera.read_noise_level * full_scale_;
  for (int b = 0; b < std::max(camera.background_frames, 1); ++b) {
    cv::Mat background = make_frame();
    for (int r = 0; r < rows_; ++r) {
      for (int c = 0; c < columns_; ++c) {
        const double value =
            std::clamp(std::round(ambient + read_noise * background_random.normal()), 0.0,
                       static_cast<double>(full_scale_));
        if (background.depth() == CV_8U) {
          background.ptr<std::uint8_t>(r)[c] = static_cast<std::uint8_t>(value);
        } else {
          background.ptr<std::uint16_t>(r)[c] = static_cast<std::uint16_t>(value);
        }
      }
    }
    backgrounds_.push_back(background);
  }
}

cv::Mat CameraFrameRenderer::make_frame() const {
  return cv::Mat(rows_, columns_, parameters_.camera.bit_depth == 8 ? CV_8UC1 : CV_16UC1,
                 cv::Scalar(0));
}

StripeExtractionParameters CameraFrameRenderer::extraction_parameters() const {
  const CameraFrameParameters& camera = parameters_.camera;
  StripeExtractionParameters extraction;
  extraction.method = StripePeakMethod::kCentreOfGravity;
  extraction.threshold = static_cast<int>(std::lround(camera.threshold_level * full_scale_));
  extraction.min_peak_intensity = static_cast<int>(
      std::lround(parameters_.min_reflected_intensity * camera.stripe_peak_level * full_scale_));
  extraction.window_half_width_px = half_taps_ + 1;
  extraction.saturation_level = full_scale_;
  return extraction;
}

double CameraFrameRenderer::next_normal() {
  const double value = normal_pool_[pool_position_];
  pool_position_ = (pool_position_ + 1) & (kPoolSize - 1);
  return value;
}

void CameraFrameRenderer::draw_column(int column, double row_px, double intensity, cv::Mat& frame) {
  const CameraFrameParameters& camera = parameters_.camera;
  const double peak = camera.stripe_peak_level * full_scale_ * intensity;
  const double electrons_per_level = camera.full_well_electrons / full_scale_;
  const double floor_row = std::floor(row_px);
  const int phase = std::min(static_cast<int>((row_px - floor_row) * kPhases), kPhases - 1);
  const int taps = 2 * half_taps_ + 2;
  const float* tap = &taps_[static_cast<std::size_t>(phase * taps)];
  const int first_row = static_cast<int>(floor_row) - half_taps_;
  for (int t = 0; t < taps; ++t) {
    const int row = first_row + t;
    if (row < 0 || row >= rows_) continue;
    const double signal = peak * tap[t];
    const double speckled = std::max(0.0, signal * (1.0 + camera.speckle_contrast * next_normal()));
    const double shot = std::sqrt(speckled / electrons_per_level) * next_normal();
    const double value = speckled + shot;
    if (frame.depth() == CV_8U) {
      add_to_pixel<std::uint8_t>(frame, row, column, value, full_scale_);
    } else {
      add_to_pixel<std::uint16_t>(frame, row, column, value, full_scale_);
    }
  }
}

void CameraFrameRenderer::render(const LaserLine& line, std::uint64_t frame_seed, cv::Mat& frame) {
  SeededRandom random(frame_seed);
  backgrounds_[random.next() % backgrounds_.size()].copyTo(frame);
  pool_position_ = random.next() & (kPoolSize - 1);
  const double roi_first_row = geometry_.roi_row_offset_px;
  const int n = line.width();
  const auto draw = [&](int column, double v, double intensity) {
    if (column >= 0 && column < columns_) draw_column(column, v - roi_first_row, intensity, frame);
  };
  for (int i = 0; i < n; ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (!drawable(line.state[s])) continue;
    const bool joins_next = i + 1 < n && drawable(line.state[s + 1]) &&
                            std::abs(line.z_mm[s + 1] - line.z_mm[s]) <= max_z_jump_mm_;
    const bool joined_previous = i > 0 && drawable(line.state[s - 1]) &&
                                 std::abs(line.z_mm[s] - line.z_mm[s - 1]) <= max_z_jump_mm_;
    if (!joins_next) {
      // A lone point still lights its nearest column.
      if (!joined_previous)
        draw(static_cast<int>(std::lround(line.u_px[s])), line.v_px[s], line.intensity[s]);
      continue;
    }
    // Columns c with u_a <= c < u_b: consecutive segments share no column.
    const double ua = line.u_px[s];
    const double ub = line.u_px[s + 1];
    const double low = std::min(ua, ub);
    const double high = std::max(ua, ub);
    for (int c = static_cast<int>(std::ceil(low)); c < high; ++c) {
      const double t = (c - ua) / (ub - ua);
      draw(c, line.v_px[s] + t * (line.v_px[s + 1] - line.v_px[s]),
           line.intensity[s] + t * (line.intensity[s + 1] - line.intensity[s]));
    }
  }
}

}  // namespace cosmos
