#include "sim/calibration_targets/calibration_target_simulator.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "scanner/sheet_pitch.hpp"
#include "sim/calibration_targets/board_image_renderer.hpp"
#include "sim/calibration_targets/target_stripe_renderer.hpp"
#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr double kBeltReflectance = 0.5;
// Where the targets start on the belt: upstream of the sheet by this much at tick 0.
constexpr double kLeadMm = 20.0;
constexpr std::array<std::array<double, 2>, 4> kSpheresOnPlate = {
    {{-60.0, 25.0}, {50.0, 40.0}, {-25.0, 115.0}, {65.0, 120.0}}};

SurfacePoint belt_point() {
  SurfacePoint point;
  point.reflectance = kBeltReflectance;
  return point;
}

// The surface a pitched sheet lights at one x: the laser comes down the sheet, so of the
// surfaces the sheet's line meets, the one highest along it. Offered in any order; the belt
// (in-sheet height 0) where none is met.
class SheetHit {
 public:
  SheetHit(const SheetPitch& pitch, double x_mm, double foot_y_mm)
      : pitch_(pitch), x_mm_(x_mm), foot_y_mm_(foot_y_mm), point_(belt_point()) {}

  // A top z = a + b (y − y0) over y in [y_low, y_high].
  void sloped_top(double a_mm, double b, double y0_mm, double y_low_mm, double y_high_mm,
                  const Eigen::Vector3d& normal, double reflectance) {
    const double s = (a_mm + b * (foot_y_mm_ - y0_mm)) / (pitch_.cos() - b * pitch_.sin());
    const double y = foot_y_mm_ + s * pitch_.sin();
    if (s >= 0.0 && y >= y_low_mm && y <= y_high_mm) offer(s, normal, reflectance);
  }
  // A vertical end face y = y_face from the belt up to height_mm, facing ±y (outward_y).
  // An unpitched sheet never lights one: it is parallel to the face.
  void end_face(double y_face_mm, double height_mm, double outward_y, double reflectance) {
    if (!pitch_.pitched()) return;
    const double s = (y_face_mm - foot_y_mm_) / pitch_.sin();
    if (s >= 0.0 && s * pitch_.cos() <= height_mm)
      offer(s, Eigen::Vector3d(0.0, outward_y, 0.0), reflectance);
  }
  void sphere(const Eigen::Vector3d& centre, double radius_mm, double reflectance) {
    const Eigen::Vector3d up = pitch_.up_belt();
    const Eigen::Vector3d d = centre - Eigen::Vector3d(x_mm_, foot_y_mm_, 0.0);
    const double along = up.dot(d);
    const double off_line2 = (d - along * up).squaredNorm();
    if (off_line2 >= radius_mm * radius_mm) return;
    const double s = along + std::sqrt(radius_mm * radius_mm - off_line2);
    offer(s, (pitch_.belt_point(x_mm_, foot_y_mm_, s) - centre) / radius_mm, reflectance);
  }

  const SurfacePoint& point() const { return point_; }

 private:
  void offer(double s_mm, const Eigen::Vector3d& normal, double reflectance) {
    if (s_mm <= point_.s_mm) return;
    point_.s_mm = s_mm;
    point_.normal = normal;
    point_.reflectance = reflectance;
  }

  SheetPitch pitch_;
  double x_mm_;
  double foot_y_mm_;
  SurfacePoint point_;
};

}  // namespace

CalibrationTargetSimulator::CalibrationTargetSimulator(const ScannerParameters& nominal,
                                                       const SimulatedMounting& truth,
                                                       std::uint64_t seed)
    : nominal_(nominal),
      mounting_(truth),
      geometry_(true_triangulation_geometry(nominal, truth)),
      seed_(seed) {}

CalibrationTruth CalibrationTargetSimulator::truth() const {
  CalibrationTruth truth;
  const CameraIntrinsics& k = geometry_.camera;
  truth.camera.calibrated = true;
  truth.camera.fx_px = k.fx_px;
  truth.camera.fy_px = k.fy_px;
  truth.camera.cx_px = k.cx_px;
  truth.camera.cy_px = k.cy_px;
  truth.camera.k1 = k.k1;
  truth.laser = laser_plane_in_camera(geometry_);
  truth.T_scanner_camera = {geometry_.R_scanner_camera, geometry_.t_scanner_camera_mm};
  truth.encoder_mm_per_tick = true_scanner_parameters(nominal_, mounting_).encoder_mm_per_tick;
  truth.T_cell_scanner = mounting_.T_cell_scanner;
  truth.roll_deg = mounting_.roll_deg;
  truth.sheet_pitch_deg = mounting_.sheet_pitch_deg;
  truth.camera_height_mm = geometry_.t_scanner_camera_mm.z();
  return truth;
}

StripeExtractionParameters CalibrationTargetSimulator::extraction_parameters() const {
  return TargetStripeRenderer(nominal_, geometry_, 0, 16).extraction_parameters();
}

RigidTransform CalibrationTargetSimulator::T_camera_belt() const {
  return RigidTransform{geometry_.R_scanner_camera, geometry_.t_scanner_camera_mm}.inverse();
}

RigidTransform CalibrationTargetSimulator::random_board_pose(const CalibrationBoard& board,
                                                             bool facing_camera,
                                                             double max_tilt_deg,
                                                             double y_half_range_mm,
                                                             double z_max_mm) {
  SeededRandom random(mix_seed(seed_, 0xB0A4D + draws_++));
  const auto uniform = [&](double low, double high) {
    return low + (high - low) * random.uniform();
  };
  const Eigen::Vector3d centre_board((board.inner_columns - 1) * board.square_mm * 0.5,
                                     (board.inner_rows - 1) * board.square_mm * 0.5, 0.0);
  // The printed board's outline must be in view, not only its corners: the detector needs
  // the white margin around the pattern.
  const double sq = board.square_mm;
  const std::vector<Eigen::Vector3d> outline = {
      {-2 * sq, -2 * sq, 0},
      {(board.inner_columns + 1) * sq, -2 * sq, 0},
      {-2 * sq, (board.inner_rows + 1) * sq, 0},
      {(board.inner_columns + 1) * sq, (board.inner_rows + 1) * sq, 0}};
  const CameraIntrinsics& k = geometry_.camera;
  for (int attempt = 0; attempt < 1000; ++attempt) {
    // Printed side up (the board's z axis down into the belt, away from the camera), or
    // square to the camera's axis (the board frame along the camera frame).
    const Eigen::Matrix3d face_up =
        facing_camera
            ? geometry_.R_scanner_camera
            : Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
    const Eigen::Matrix3d tilt =
        (Eigen::AngleAxisd(uniform(-12, 12) * kRadPerDeg, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(uniform(-max_tilt_deg, max_tilt_deg) * kRadPerDeg,
                           Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(uniform(-max_tilt_deg, max_tilt_deg) * kRadPerDeg,
                           Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    RigidTransform T_belt_board;
    T_belt_board.rotation = facing_camera ? face_up * tilt : tilt * face_up;
    const Eigen::Vector3d centre_belt(uniform(-45, 45), uniform(-y_half_range_mm, y_half_range_mm),
                                      uniform(0, z_max_mm));
    T_belt_board.translation_mm = centre_belt - T_belt_board.rotation * centre_board;
    bool visible = true;
    for (const Eigen::Vector3d& c : outline) {
      const Eigen::Vector3d p = T_belt_board.apply(c);
      Eigen::Vector2d uv;
      if (p.z() < -1.0 || !geometry_.project_to_image(p, uv) || uv.x() < 20 ||
          uv.x() > k.width_px - 21 || uv.y() < 20 || uv.y() > k.height_px - 21) {
        visible = false;
        break;
      }
    }
    if (visible) return T_belt_board;
  }
  throw std::invalid_argument("calibration targets: the board does not fit the camera's view");
}

std::vector<BoardImage> CalibrationTargetSimulator::board_images(const CalibrationBoard& board,
                                                                 int count) {
  const BoardImageRenderer renderer(geometry_, nominal_.camera);
  std::vector<BoardImage> images;
  for (int i = 0; i < count; ++i) {
    const RigidTransform T_camera_board =
        T_camera_belt() * random_board_pose(board, true, 40.0, 40.0, 60.0);
    images.push_back({renderer.render(board, T_camera_board, mix_seed(seed_, 0xCA1 + draws_++)),
                      T_camera_board});
  }
  return images;
}

std::vector<LaserImagePair> CalibrationTargetSimulator::laser_views(const CalibrationBoard& board,
                                                                    int count) {
  const BoardImageRenderer board_renderer(geometry_, nominal_.camera);
  TargetStripeRenderer stripe_renderer(nominal_, geometry_, 0, geometry_.camera.height_px);
  std::vector<LaserImagePair> views;
  for (int i = 0; i < count; ++i) {
    // Heights spread over the measuring range, so the lines span the plane.
    const double z_max = 10.0 + 90.0 * i / std::max(1, count - 1);
    const RigidTransform T_belt_board = random_board_pose(board, false, 20.0, 8.0, z_max);
    const RigidTransform T_camera_board = T_camera_belt() * T_belt_board;
    const RigidTransform T_board_belt = T_belt_board.inverse();
    const Eigen::Vector3d normal = T_belt_board.rotation.col(2);
    const double offset = normal.dot(T_belt_board.translation_mm);
    const SheetProfile on_board = [&](double x, SurfacePoint& point) {
      if (std::abs(normal.z()) < 1e-6) return false;
      const double z = (offset - normal.x() * x) / normal.z();
      const Eigen::Vector3d b = T_board_belt.apply(Eigen::Vector3d(x, 0.0, z));
      const double reflectance = board_reflectance(board, b.x(), b.y());
      if (reflectance < 0 || z < 0) {
        point = belt_point();
        return true;
      }
      point.s_mm = z;
      point.normal = normal.z() > 0 ? Eigen::Vector3d(normal) : Eigen::Vector3d(-normal);
      point.reflectance = reflectance / BoardImageRenderer::kWhiteLevel;
      return true;
    };
    views.push_back(
        {board_renderer.render(board, T_camera_board, mix_seed(seed_, 0x1A5 + draws_++)),
         stripe_renderer.render(on_board, mix_seed(seed_, 0x1A6 + draws_++)), T_camera_board});
  }
  return views;
}

std::vector<StripeFrame> CalibrationTargetSimulator::empty_belt_frames(int count) {
  TargetStripeRenderer renderer(nominal_, geometry_,
                                scanner_triangulation_geometry(nominal_).roi_row_offset_px,
                                scanner_triangulation_geometry(nominal_).roi_height_px);
  std::vector<StripeFrame> frames;
  const SheetProfile belt = [](double, SurfacePoint& point) {
    point = belt_point();
    return true;
  };
  const int roi_top = scanner_triangulation_geometry(nominal_).roi_row_offset_px;
  for (int i = 0; i < count; ++i)
    frames.push_back({renderer.render(belt, mix_seed(seed_, 0xBE17 + draws_++)), roi_top,
                      static_cast<std::int64_t>(i) * nominal_.encoder_ticks_per_profile});
  return frames;
}

std::vector<StripeFrame> CalibrationTargetSimulator::ramp_frames(const RampBlock& block,
                                                                 int ticks_between_frames,
                                                                 RampPlacement placement) {
  const TriangulationGeometry designed = scanner_triangulation_geometry(nominal_);
  TargetStripeRenderer renderer(nominal_, geometry_, designed.roi_row_offset_px,
                                designed.roi_height_px, mounting_.sheet_pitch_deg);
  const SheetPitch pitch(mounting_.sheet_pitch_deg);
  const double mm_per_tick = true_scanner_parameters(nominal_, mounting_).encoder_mm_per_tick;
  const double y_end = -kLeadMm;  // the block's downstream end, belt frame
  const double y_start = y_end - block.length_mm;
  // Rising downstream, or turned round on the belt: rising upstream.
  const bool reversed = placement == RampPlacement::kHighEndUpstream;
  const double slope = reversed ? -block.rise_per_mm() : block.rise_per_mm();
  const double start_height = reversed ? block.high_height_mm : block.low_height_mm;
  const double end_height = start_height + slope * block.length_mm;
  const Eigen::Vector3d ramp_normal = Eigen::Vector3d(0.0, -slope, 1.0).normalized();
  std::vector<StripeFrame> frames;
  const auto last_tick = static_cast<std::int64_t>((2.0 * kLeadMm + block.length_mm) / mm_per_tick);
  for (std::int64_t tick = 0; tick <= last_tick; tick += ticks_between_frames) {
    const double foot_y = -static_cast<double>(tick) * mm_per_tick;
    const SheetProfile ramp = [&](double x, SurfacePoint& point) {
      SheetHit hit(pitch, x, foot_y);
      if (std::abs(x) < 0.5 * block.width_mm) {
        hit.sloped_top(start_height, slope, y_start, y_start, y_end, ramp_normal, 1.0);
        hit.end_face(y_start, start_height, -1.0, 1.0);
        hit.end_face(y_end, end_height, 1.0, 1.0);
      }
      point = hit.point();
      return true;
    };
    frames.push_back({renderer.render(ramp, mix_seed(seed_, 0x4A3 + draws_++)),
                      designed.roi_row_offset_px, tick});
  }
  return frames;
}

SpherePlateScan CalibrationTargetSimulator::sphere_plate_scan(int ticks_between_frames) {
  const TriangulationGeometry designed = scanner_triangulation_geometry(nominal_);
  TargetStripeRenderer renderer(nominal_, geometry_, designed.roi_row_offset_px,
                                designed.roi_height_px, mounting_.sheet_pitch_deg);
  const SheetPitch pitch(mounting_.sheet_pitch_deg);
  const double mm_per_tick = true_scanner_parameters(nominal_, mounting_).encoder_mm_per_tick;
  SpherePlateScan scan;
  SpherePlate& plate = scan.plate;
  const double y_start = -kLeadMm - kPlateLengthMm;
  const double y_end = y_start + kPlateLengthMm;
  std::vector<Eigen::Vector3d> centres_belt;
  for (const auto& [x, y] : kSpheresOnPlate)
    centres_belt.emplace_back(x, y_start + y, plate.plate_height_mm + plate.radius_mm);
  const auto last_tick = static_cast<std::int64_t>((2.0 * kLeadMm + kPlateLengthMm) / mm_per_tick);
  for (std::int64_t tick = 0; tick <= last_tick; tick += ticks_between_frames) {
    const double foot_y = -static_cast<double>(tick) * mm_per_tick;
    const SheetProfile plate_profile = [&](double x, SurfacePoint& point) {
      SheetHit hit(pitch, x, foot_y);
      if (std::abs(x) <= 0.5 * kPlateWidthMm) {
        hit.sloped_top(plate.plate_height_mm, 0.0, y_start, y_start, y_end,
                       Eigen::Vector3d::UnitZ(), 0.8);
        hit.end_face(y_start, plate.plate_height_mm, -1.0, 0.8);
        hit.end_face(y_end, plate.plate_height_mm, 1.0, 0.8);
        for (const Eigen::Vector3d& c : centres_belt) hit.sphere(c, plate.radius_mm, 1.0);
      }
      point = hit.point();
      return true;
    };
    scan.frames.push_back({renderer.render(plate_profile, mix_seed(seed_, 0x5F3 + draws_++)),
                           designed.roi_row_offset_px, tick});
  }
  plate.encoder_ticks = last_tick;
  const Eigen::Vector3d travel(0.0, static_cast<double>(last_tick) * mm_per_tick, 0.0);
  for (const Eigen::Vector3d& c : centres_belt)
    plate.centres_cell_mm.push_back(mounting_.T_cell_scanner.apply(c + travel));
  return scan;
}

}  // namespace cosmos
