#include "calibration/belt_calibration.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "calibration/stripe_points.hpp"

namespace cosmos {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// Points in the camera frame: the geometry with the camera at the camera frame's origin.
TriangulationGeometry camera_frame_geometry(const ScannerParameters& nominal,
                                            const ScannerCalibration& calibration) {
  ScannerCalibration in_camera = calibration;
  in_camera.mount.calibrated = true;
  in_camera.mount.T_scanner_camera = RigidTransform::identity();
  return calibrated_triangulation_geometry(nominal, in_camera);
}

struct Line {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};

Line fit_line(const std::vector<Eigen::Vector3d>& points) {
  Line line;
  for (const Eigen::Vector3d& p : points) line.point += p;
  line.point /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points)
    scatter += (p - line.point) * (p - line.point).transpose();
  line.direction = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(2);
  return line;
}

// Least squares z = a + b x.
Eigen::Vector2d fit_straight_line(const std::vector<Eigen::Vector2d>& xz, double* rms) {
  Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : xz) {
    const Eigen::Vector2d row(1.0, p.x());
    a += row * row.transpose();
    b += row * p.y();
  }
  const Eigen::Vector2d solution = a.ldlt().solve(b);
  double sum = 0.0;
  for (const Eigen::Vector2d& p : xz) {
    const double r = p.y() - solution(0) - solution(1) * p.x();
    sum += r * r;
  }
  if (rms) *rms = std::sqrt(sum / std::max<std::size_t>(1, xz.size()));
  return solution;
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The ramp's top height in each frame (the median of the points above the belt) over the
// middle 70 % of its rise, and the straight line of height against encoder count.
// `why` is left empty when the scan is usable.
RampLine fit_ramp_line(const std::vector<StripeFrame>& frames, const RampBlock& block,
                       const TriangulationGeometry& geometry,
                       const StripeExtractionParameters& extraction, std::string& why) {
  RampLine line;
  char reason[200];
  const double rise = block.high_height_mm - block.low_height_mm;
  const double low = block.low_height_mm + 0.15 * rise;
  const double high = block.high_height_mm - 0.15 * rise;
  for (const StripeFrame& frame : frames) {
    std::vector<double> heights;
    for (const Eigen::Vector3d& p :
         stripe_scanner_points(frame.image, frame.roi_top_px, geometry, extraction))
      if (p.z() > 0.5 * block.low_height_mm) heights.push_back(p.z());
    if (heights.size() < 20) continue;
    const double height = median(std::move(heights));
    if (height > low && height < high)
      line.ticks_height.emplace_back(static_cast<double>(frame.encoder_ticks), height);
  }
  if (line.ticks_height.size() < 5) {
    std::snprintf(reason, sizeof reason,
                  "%zu frames see its slope (heights %.1f to %.1f mm), at least 5 needed: is it "
                  "the block of the target file?",
                  line.ticks_height.size(), low, high);
    why = reason;
    return line;
  }
  line.slope_mm_per_tick = fit_straight_line(line.ticks_height, &line.rms_mm)(1);
  if (line.rms_mm > 0.5) {
    std::snprintf(reason, sizeof reason,
                  "its heights leave a straight line by %.2f mm RMS: not a ramp of the target "
                  "file's shape",
                  line.rms_mm);
    why = reason;
  }
  return line;
}

}  // namespace

BeltCalibrationResult calibrate_belt(const std::vector<StripeFrame>& empty_belt,
                                     const std::vector<StripeFrame>& ramp,
                                     const std::vector<StripeFrame>& ramp_turned,
                                     const RampBlock& block, const ScannerParameters& nominal,
                                     const ScannerCalibration& calibration,
                                     const StripeExtractionParameters& extraction) {
  BeltCalibrationResult result;
  char reason[200];
  const TriangulationGeometry camera_geometry = camera_frame_geometry(nominal, calibration);
  std::vector<Eigen::Vector3d> belt_camera;
  for (const StripeFrame& frame : empty_belt) {
    const std::vector<Eigen::Vector3d> points =
        stripe_scanner_points(frame.image, frame.roi_top_px, camera_geometry, extraction);
    belt_camera.insert(belt_camera.end(), points.begin(), points.end());
  }
  if (belt_camera.size() < 100) {
    std::snprintf(reason, sizeof reason,
                  "empty belt: %zu stripe points in %zu frames, at least 100 needed",
                  belt_camera.size(), empty_belt.size());
    result.reason = reason;
    return result;
  }
  const Eigen::Vector3d normal = camera_geometry.laser_plane.normal_scanner;
  const double offset = camera_geometry.laser_plane.offset_mm;
  const Eigen::Vector3d y_axis = offset >= 0 ? normal : Eigen::Vector3d(-normal);
  const Line line = fit_line(belt_camera);
  Eigen::Vector3d x_axis = line.direction - line.direction.dot(y_axis) * y_axis;
  x_axis.normalize();
  if (x_axis.x() < 0) x_axis = -x_axis;
  const Eigen::Vector3d z_axis = x_axis.cross(y_axis);
  if (z_axis.dot(-line.point) <= 0) {
    result.reason = "empty belt: the stripe's line lies above the camera: wrong laser plane?";
    return result;
  }
  // Where the optical axis meets the sheet, dropped onto the belt's line.
  const Eigen::Vector3d axis_on_sheet(0.0, 0.0, offset / normal.z());
  const Eigen::Vector3d origin = line.point + (axis_on_sheet - line.point).dot(x_axis) * x_axis;
  RigidTransform T_camera_scanner;
  T_camera_scanner.rotation.col(0) = x_axis;
  T_camera_scanner.rotation.col(1) = y_axis;
  T_camera_scanner.rotation.col(2) = z_axis;
  T_camera_scanner.translation_mm = origin;
  const RigidTransform T_scanner_camera = T_camera_scanner.inverse();
  result.mount.calibrated = true;
  result.mount.T_scanner_camera = T_scanner_camera;
  const Eigen::Vector3d camera_x = T_scanner_camera.rotation.col(0);
  result.roll_deg = std::atan2(-camera_x.z(), camera_x.x()) * kDegPerRad;
  result.camera_height_mm = T_scanner_camera.translation_mm.z();

  std::vector<Eigen::Vector2d> belt_xz;
  for (const Eigen::Vector3d& p : belt_camera) {
    const Eigen::Vector3d s = T_scanner_camera.apply(p);
    result.belt_points_scanner.push_back(s);
    belt_xz.emplace_back(s.x(), s.z());
  }
  const Eigen::Vector2d belt = fit_straight_line(belt_xz, &result.belt_rms_mm);
  result.belt_height_mm = belt(0);
  result.belt_slope_x = belt(1);

  // The ramp's top height per frame, in the new frame.
  ScannerCalibration mounted = calibration;
  mounted.mount = result.mount;
  const TriangulationGeometry geometry = calibrated_triangulation_geometry(nominal, mounted);
  // Each scan's line, or the reason it is unusable, named after the scan.
  const auto fit = [&](const std::vector<StripeFrame>& frames, const char* scan, RampLine& line) {
    std::string why;
    line = fit_ramp_line(frames, block, geometry, extraction, why);
    if (!why.empty()) result.reason = scan + (": " + why);
    return why.empty();
  };
  if (!fit(ramp, "ramp block", result.ramp)) return result;
  const double rise = block.rise_per_mm();
  if (ramp_turned.empty()) {
    result.encoder_mm_per_tick = std::abs(result.ramp.slope_mm_per_tick) / rise;
    result.ok = true;
    return result;
  }
  if (!fit(ramp_turned, "turned ramp block", result.ramp_turned)) return result;
  // The top z = a + b·y (b = ±rise) met by the sheet from its foot at y = −m·ticks: its
  // in-sheet height s solves s·cos p = a + b·(y + s·sin p), so ds/dticks = −b·m / (cos p −
  // b·sin p). The block as drawn (high end downstream, b = +rise) falls with the ticks, turned
  // round it rises; with k the two slopes, 1/k_up − 1/k_down = 2·cos p / (rise·m) and
  // 1/k_up + 1/k_down = 2·sin p / m.
  const double k_first = result.ramp.slope_mm_per_tick;
  const double k_second = result.ramp_turned.slope_mm_per_tick;
  const double k_down = k_first < 0.0 ? k_first : k_second;
  const double k_up = k_first < 0.0 ? k_second : k_first;
  if (!(k_down < 0.0 && k_up > 0.0)) {
    result.reason =
        "ramp block: both scans' heights change the same way with the encoder: turn the block "
        "round for the second scan";
    return result;
  }
  const double difference = 1.0 / k_up - 1.0 / k_down;
  const double sum = 1.0 / k_up + 1.0 / k_down;
  const double pitch = std::atan2(sum, difference * rise);
  result.sheet_pitch_deg = pitch * kDegPerRad;
  result.pitch_measured = true;
  result.encoder_mm_per_tick = 2.0 * std::cos(pitch) / (rise * difference);
  result.ok = true;
  return result;
}

ProfileSampling profile_sampling_for(const ScannerParameters& scanner,
                                     const ConditioningParameters& conditioning,
                                     double encoder_mm_per_tick) {
  ProfileSampling sampling;
  const double pitch_mm = encoder_mm_per_tick * scanner.encoder_ticks_per_profile;
  sampling.field_of_view_mm = pitch_mm * scanner.points_per_profile;
  sampling.conditioning = conditioning;
  sampling.conditioning.grid_mm = pitch_mm;
  sampling.conditioning.x_min_mm = -0.5 * sampling.field_of_view_mm + 0.5 * pitch_mm;
  sampling.conditioning.x_max_mm =
      sampling.conditioning.x_min_mm + pitch_mm * scanner.points_per_profile;
  return sampling;
}

}  // namespace cosmos
