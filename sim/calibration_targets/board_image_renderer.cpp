#include "sim/calibration_targets/board_image_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>

#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

// A square wave of period 2 · square_mm (+1, −1), box-filtered over `footprint_mm`.
double smoothed_square_wave(double t_mm, double square_mm, double footprint_mm) {
  const double u = t_mm / square_mm;
  const double cell = std::floor(u);
  const double f = u - cell;
  const double parity = (static_cast<long long>(cell) & 1) ? -1.0 : 1.0;
  const double to_edge_mm = std::min(f, 1.0 - f) * square_mm;
  return parity * std::min(1.0, to_edge_mm / (0.5 * footprint_mm));
}

bool on_board(const CalibrationBoard& board, double x_mm, double y_mm) {
  const double sq = board.square_mm;
  return x_mm > -2.0 * sq && x_mm < (board.inner_columns + 1) * sq && y_mm > -2.0 * sq &&
         y_mm < (board.inner_rows + 1) * sq;
}

bool in_pattern(const CalibrationBoard& board, double x_mm, double y_mm) {
  const double sq = board.square_mm;
  return x_mm > -sq && x_mm < board.inner_columns * sq && y_mm > -sq &&
         y_mm < board.inner_rows * sq;
}

}  // namespace

double board_reflectance(const CalibrationBoard& board, double x_mm, double y_mm) {
  if (!on_board(board, x_mm, y_mm)) return -1.0;
  if (!in_pattern(board, x_mm, y_mm)) return BoardImageRenderer::kWhiteLevel;
  const double sq = board.square_mm;
  const bool white = ((static_cast<long long>(std::floor(x_mm / sq)) +
                       static_cast<long long>(std::floor(y_mm / sq))) &
                      1) != 0;
  return white ? BoardImageRenderer::kWhiteLevel : BoardImageRenderer::kBlackLevel;
}

BoardImageRenderer::BoardImageRenderer(const TriangulationGeometry& true_geometry,
                                       const CameraFrameParameters& levels)
    : geometry_(true_geometry), levels_(levels) {
  const CameraIntrinsics& k = geometry_.camera;
  std::vector<cv::Point2f> pixels;
  pixels.reserve(static_cast<std::size_t>(k.width_px) * static_cast<std::size_t>(k.height_px));
  for (int v = 0; v < k.height_px; ++v)
    for (int u = 0; u < k.width_px; ++u)
      pixels.emplace_back(static_cast<float>(u), static_cast<float>(v));
  cv::undistortPoints(pixels, normalized_, k.camera_matrix(), k.distortion_coefficients(),
                      cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-10));
}

cv::Mat BoardImageRenderer::render(const CalibrationBoard& board,
                                   const RigidTransform& T_camera_board, std::uint64_t seed) const {
  const CameraIntrinsics& k = geometry_.camera;
  cv::Mat image(k.height_px, k.width_px, CV_8UC1);
  const Eigen::Vector3d normal = T_camera_board.rotation.col(2);
  const double offset = normal.dot(T_camera_board.translation_mm);
  const RigidTransform T_board_camera = T_camera_board.inverse();
  const double sq = board.square_mm;
  const double full_scale = 255.0;
  const double electrons_per_level = levels_.full_well_electrons / full_scale;
  SeededRandom random(seed);
  for (int v = 0; v < k.height_px; ++v) {
    auto* row = image.ptr<std::uint8_t>(v);
    for (int u = 0; u < k.width_px; ++u) {
      const cv::Point2f& n = normalized_[static_cast<std::size_t>(v) * k.width_px + u];
      const Eigen::Vector3d ray(n.x, n.y, 1.0);
      const double along = normal.dot(ray);
      double level = kBeltLevel;
      if (std::abs(along) > 1e-9) {
        const double s = offset / along;
        const Eigen::Vector3d b = T_board_camera.apply(s * ray);
        if (s > 0 && on_board(board, b.x(), b.y())) {
          level = kWhiteLevel;
          if (in_pattern(board, b.x(), b.y())) {
            // The pixel's footprint on the board, widened by the board's obliquity.
            const double footprint_mm =
                s * ray.norm() / k.fx_px / std::max(0.2, std::abs(along) / ray.norm());
            const double checker = smoothed_square_wave(b.x(), sq, footprint_mm) *
                                   smoothed_square_wave(b.y(), sq, footprint_mm);
            level = kBlackLevel + (kWhiteLevel - kBlackLevel) * 0.5 * (1.0 - checker);
          }
        }
      }
      const double signal = level * full_scale;
      const double noisy = signal + std::sqrt(signal / electrons_per_level) * random.normal() +
                           levels_.read_noise_level * full_scale * random.normal();
      row[u] = static_cast<std::uint8_t>(std::clamp(std::round(noisy), 0.0, full_scale));
    }
  }
  return image;
}

}  // namespace cosmos
