#include "sim/calibration_targets/target_stripe_renderer.hpp"

#include <cmath>

namespace cosmos {

TargetStripeRenderer::TargetStripeRenderer(const ScannerParameters& scanner,
                                           const TriangulationGeometry& true_geometry,
                                           int roi_top_px, int rows_px, double sheet_pitch_deg)
    : scanner_(scanner), geometry_(true_geometry), pitch_(sheet_pitch_deg) {
  TriangulationGeometry drawing = geometry_;
  drawing.roi_row_offset_px = roi_top_px;
  drawing.roi_height_px = rows_px;
  renderer_ = std::make_unique<CameraFrameRenderer>(scanner_, drawing);
  // Two samples per sensor column over a little more than the field of view, so every
  // column under the lit line is drawn.
  const int samples = 2 * scanner_.sensor_width_px;
  const double span_mm = 1.3 * scanner_.field_of_view_mm;
  line_.x0_mm = -0.5 * span_mm;
  line_.dx_mm = span_mm / samples;
  const auto n = static_cast<std::size_t>(samples);
  line_.z_mm.assign(n, 0.0f);
  line_.intensity.assign(n, 0.0f);
  line_.u_px.assign(n, 0.0f);
  line_.v_px.assign(n, 0.0f);
  line_.state.assign(n, LaserSampleState::kOutOfRange);
  frame_ = renderer_->make_frame();
}

cv::Mat TargetStripeRenderer::render(const SheetProfile& profile, std::uint64_t frame_seed) {
  const Eigen::Vector3d camera_centre = geometry_.t_scanner_camera_mm;
  for (int i = 0; i < line_.width(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    line_.state[s] = LaserSampleState::kOutOfRange;
    SurfacePoint point;
    if (!profile(line_.x_mm(i), point)) continue;
    const Eigen::Vector3d p(line_.x_mm(i), 0.0, point.s_mm);
    const Eigen::Vector3d normal_sheet = pitch_.R_belt_sheet().transpose() * point.normal;
    Eigen::Vector2d uv;
    if (normal_sheet.dot(camera_centre - p) <= 0.0 || !geometry_.project_to_image(p, uv)) continue;
    // The laser comes down the sheet: Lambertian in the incidence along it.
    const double intensity = point.reflectance * std::abs(normal_sheet.z());
    line_.z_mm[s] = static_cast<float>(point.s_mm);
    line_.u_px[s] = static_cast<float>(uv.x());
    line_.v_px[s] = static_cast<float>(uv.y());
    line_.intensity[s] = static_cast<float>(intensity);
    line_.state[s] = LaserSampleState::kMeasured;
  }
  renderer_->render(line_, frame_seed, frame_);
  return frame_.clone();
}

}  // namespace cosmos
