#include "sim/calibration_targets/board_image_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>

#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

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
  const int width = k.width_px;
  const int height = k.height_px;
  cv::Mat image(height, width, CV_8UC1);
  const Eigen::Vector3d normal = T_camera_board.rotation.col(2);
  const double offset = normal.dot(T_camera_board.translation_mm);
  const RigidTransform T_board_camera = T_camera_board.inverse();
  const double sq = board.square_mm;
  const double full_scale = 255.0;
  const double electrons_per_level = levels_.full_well_electrons / full_scale;
  // The print's level at a normalized ray; `edge` says whether a print edge lies within
  // `reach_mm` of the point (then the pixel is supersampled).
  const auto level_at = [&](double xn, double yn, double reach_mm, bool* edge) {
    const Eigen::Vector3d ray(xn, yn, 1.0);
    const double along = normal.dot(ray);
    if (std::abs(along) < 1e-9) return kBeltLevel;
    const double s = offset / along;
    if (s <= 0) return kBeltLevel;
    const Eigen::Vector3d b = T_board_camera.apply(s * ray);
    if (edge) {
      const auto near_grid = [&](double t) {
        const double f = t / sq - std::floor(t / sq);
        return std::min(f, 1.0 - f) * sq < reach_mm;
      };
      // Squares' edges and the board's outline both lie on the square grid.
      *edge = near_grid(b.x()) || near_grid(b.y());
    }
    const double reflectance = board_reflectance(board, b.x(), b.y());
    return reflectance < 0 ? kBeltLevel : reflectance;
  };
  const auto normalized_at = [&](double u, double v) {
    const int u0 = std::clamp(static_cast<int>(std::floor(u)), 0, width - 2);
    const int v0 = std::clamp(static_cast<int>(std::floor(v)), 0, height - 2);
    const double fu = u - u0;
    const double fv = v - v0;
    const auto at = [&](int uu, int vv) {
      return normalized_[static_cast<std::size_t>(vv) * width + uu];
    };
    const cv::Point2f top = at(u0, v0) * (1 - fu) + at(u0 + 1, v0) * fu;
    const cv::Point2f bottom = at(u0, v0 + 1) * (1 - fu) + at(u0 + 1, v0 + 1) * fu;
    return top * (1 - fv) + bottom * fv;
  };
  SeededRandom random(seed);
  for (int v = 0; v < height; ++v) {
    auto* row = image.ptr<std::uint8_t>(v);
    for (int u = 0; u < width; ++u) {
      const cv::Point2f& n = normalized_[static_cast<std::size_t>(v) * width + u];
      const double depth =
          std::abs(offset / std::max(1e-9, std::abs(normal.dot(Eigen::Vector3d(n.x, n.y, 1)))));
      // Generously more than a pixel's footprint, for oblique views.
      const double reach_mm = 4.0 * depth / k.fx_px;
      bool edge = false;
      double level = level_at(n.x, n.y, reach_mm, &edge);
      if (edge) {
        // A 4 × 4 box filter over the pixel: the corners fall where a sensor's would.
        double sum = 0.0;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) {
            const cv::Point2f m = normalized_at(u - 0.375 + 0.25 * i, v - 0.375 + 0.25 * j);
            sum += level_at(m.x, m.y, 0.0, nullptr);
          }
        level = sum / 16.0;
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
