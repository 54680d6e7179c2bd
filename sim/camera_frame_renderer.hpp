#pragma once
// Camera mode: the sensor frame a real laser-triangulation camera would deliver for one laser
// line, so that the simulated cell runs firmware_bridge's stripe extraction and
// triangulation on it exactly as on hardware frames.
//
// Drawing: the lit, camera-visible samples of the line are projected with the firmware
// camera model (TriangulationGeometry::project_to_image); consecutive samples on one
// surface (no depth jump) are joined, and every sensor column under a joined segment gets a
// Gaussian stripe profile across the rows at the segment's interpolated row, with peak
// stripe_peak_level · full scale · reflected intensity. Per stripe pixel: multiplicative
// speckle, then shot noise (Poisson in electrons, Gaussian approximation), on top of the
// background; the result is rounded and clipped at full scale (saturation).
//
// Cost: the background (uniform ambient light + read noise on every pixel) comes from a few
// frames pre-rendered at construction, one picked per frame by the seeded generator, and the
// stripe pixels' noise from a pool of pre-drawn normal deviates read from a per-frame random
// start. Fresh per-pixel noise on a 1280 × 512 frame would cost more than everything else
// together, and the extractor only sees the background through its threshold.
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/scanner_model.hpp"
#include "scanner/triangulation_geometry.hpp"
#include "sim/laser_line_scanner.hpp"

namespace cosmos {

class CameraFrameRenderer {
 public:
  CameraFrameRenderer(const ScannerParameters& parameters, const TriangulationGeometry& geometry);

  // An empty frame of the right size and type (ROI rows × sensor columns) for render().
  cv::Mat make_frame() const;
  // Draws `line` into `frame` (made by make_frame; not reallocated). `frame_seed` decides the
  // background and noise, so a frame is a pure function of the line and the seed.
  void render(const LaserLine& line, std::uint64_t frame_seed, cv::Mat& frame);

  // Where the frame sits on the sensor, and the extraction settings that match the drawing
  // (threshold, minimum peak for min_reflected_intensity, window, saturation level).
  FrameRoi roi() const { return {geometry_.roi_row_offset_px, 0}; }
  StripeExtractionParameters extraction_parameters() const;

 private:
  void draw_column(int column, double row_px, double intensity, cv::Mat& frame);
  double next_normal();

  ScannerParameters parameters_;
  TriangulationGeometry geometry_;
  int full_scale_ = 255;
  int rows_ = 0;
  int columns_ = 0;
  // Gaussian stripe taps relative to floor(row), one set per 1/kPhases sub-pixel phase.
  int half_taps_ = 0;
  std::vector<float> taps_;
  std::vector<cv::Mat> backgrounds_;
  std::vector<float> normal_pool_;
  std::size_t pool_position_ = 0;
  double max_z_jump_mm_ = 0.0;
};

}  // namespace cosmos
