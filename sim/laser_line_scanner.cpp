#include "sim/laser_line_scanner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "sim/embree_scene.hpp"

namespace cosmos {
namespace {

constexpr int kPacket = 8;  // Embree's native packet width with AVX2
constexpr float kNoData = std::numeric_limits<float>::quiet_NaN();
// Occlusion rays start this far off the surface along its normal: hit points carry float
// rounding of coordinates up to a few hundred mm (~1e-5 mm), and a ray starting inside its
// own triangle's rounding would hit that triangle.
constexpr double kSurfaceOffsetMm = 1e-3;
// A top point this close to z = 0 is the belt: the probe stops just above it, so a part's
// lowest face resting on the belt does not count as part surface.
constexpr double kBeltToleranceMm = 1e-4;

}  // namespace

LaserLineScanner::LaserLineScanner(const ConveyorScene& scene, const ScannerParameters& parameters,
                                   int samples, double sheet_pitch_deg)
    : scene_(scene),
      parameters_(parameters),
      pitch_(sheet_pitch_deg),
      geometry_(scanner_triangulation_geometry(parameters)),
      samples_(samples) {
  if (samples <= 0) throw std::invalid_argument("LaserLineScanner: samples must be > 0");
  cos_max_incidence_ = std::cos(parameters.max_incidence_deg * std::numbers::pi / 180.0);
  const int margin = parameters.roi_margin_rows();
  min_roi_row_px_ = geometry_.roi_row_offset_px + margin;
  max_roi_row_px_ = geometry_.roi_row_offset_px + geometry_.roi_height_px - 1 - margin;
  // The belt's classification (incidence, image, range, brightness) is the same in every
  // profile: computed once here, it spares most samples the camera model and a normalization.
  belt_samples_.resize(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) {
    const double x_mm =
        parameters.first_sample_x_mm(samples) + i * parameters.sample_spacing_mm(samples);
    const double cos_incidence =
        (parameters.laser_model == LaserModel::kFan
             ? parameters.laser_height_mm / std::hypot(x_mm, parameters.laser_height_mm)
             : 1.0) *
        pitch_.cos();
    belt_samples_[static_cast<std::size_t>(i)] = classify_lit_point(
        Eigen::Vector3d(x_mm, 0.0, 0.0),
        pitch_.R_belt_sheet().transpose() * Eigen::Vector3d::UnitZ(), cos_incidence);
  }
  normal_x_.resize(static_cast<std::size_t>(samples));
  normal_y_.resize(static_cast<std::size_t>(samples));
  normal_z_.resize(static_cast<std::size_t>(samples));
  occlusion_candidates_.reserve(static_cast<std::size_t>(samples));
  belt_sight_marks_.resize(static_cast<std::size_t>(samples) + 1);
  belt_sights_.reserve(scene.parts().size());  // the most a line can meet
}

void LaserLineScanner::reserve(LaserLine& line) const {
  const auto n = static_cast<std::size_t>(samples_);
  line.x0_mm = parameters_.first_sample_x_mm(samples_);
  line.dx_mm = parameters_.sample_spacing_mm(samples_);
  line.z_mm.resize(n);
  line.intensity.resize(n);
  line.u_px.resize(n);
  line.v_px.resize(n);
  line.state.resize(n);
}

void LaserLineScanner::trace(double laser_y_belt_mm, LaserLine& line) {
  reserve(line);
  std::fill(line.z_mm.begin(), line.z_mm.end(), 0.0f);
  std::fill(normal_x_.begin(), normal_x_.end(), 0.0f);
  std::fill(normal_y_.begin(), normal_y_.end(), 0.0f);
  std::fill(normal_z_.begin(), normal_z_.end(), 1.0f);
  // Probe only where a part can be: the x span the parts' outlines cover at the sheet, from
  // just above the tallest of those parts. Not from above the whole scene: the probe's
  // z = top − t is rounded at the origin's magnitude, so a taller part elsewhere on the belt
  // would change this part's heights in their last bits, and a part's scan would depend on
  // which other parts ride the belt with it.
  double x_low = std::numeric_limits<double>::infinity();
  double x_high = -x_low;
  double top_z_mm = -x_low;
  // The parts the sheet can meet: those at its foot, and with a pitched sheet those within
  // its lean up to the tallest part's top.
  const double lean_mm = pitch_.pitched()
                             ? std::abs((scene_.highest_z_mm() + 1.0) * pitch_.sin() / pitch_.cos())
                             : 0.0;
  scene_.for_each_part_meeting_y(laser_y_belt_mm - lean_mm, laser_y_belt_mm + lean_mm,
                                 [&](const PlacedPart& part) {
                                   double part_low = 0.0;
                                   double part_high = 0.0;
                                   if (!sheet_x_extent(part, laser_y_belt_mm, part_low, part_high))
                                     return;
                                   x_low = std::min(x_low, part_low);
                                   x_high = std::max(x_high, part_high);
                                   top_z_mm = std::max(top_z_mm, part.bounds_mm.max().z() + 1.0);
                                 });
  if (x_low <= x_high) {
    const int first = std::max(0, static_cast<int>(std::floor((x_low - line.x0_mm) / line.dx_mm)));
    const int end =
        std::min(samples_, static_cast<int>(std::ceil((x_high - line.x0_mm) / line.dx_mm)) + 1);
    if (first < end) probe_top_surface(laser_y_belt_mm, first, end, top_z_mm, line);
  }
  sweep_laser_horizon(line);
  classify(laser_y_belt_mm, line);
  trace_camera_occlusion(laser_y_belt_mm, line);
}

bool LaserLineScanner::sheet_x_extent(const PlacedPart& part, double y_mm, double& low_mm,
                                      double& high_mm) const {
  if (!pitch_.pitched()) return part.height_bounds.x_extent(y_mm, low_mm, high_mm);
  // A pitched sheet crosses the belt over a span of y up to the part's top: the part's box
  // is a safe bound wherever that span meets it.
  const double lean_mm = (part.bounds_mm.max().z() + 1.0) * pitch_.sin() / pitch_.cos();
  const double y_low = std::min(y_mm, y_mm + lean_mm);
  const double y_high = std::max(y_mm, y_mm + lean_mm);
  if (y_high < part.bounds_mm.min().y() || y_low > part.bounds_mm.max().y()) return false;
  low_mm = part.bounds_mm.min().x();
  high_mm = part.bounds_mm.max().x();
  return true;
}

Eigen::Vector3d LaserLineScanner::camera_belt_mm(double y_mm) const {
  // The camera rides with the scanner: in the belt frame it is where the sheet frame puts it,
  // from the sheet's foot.
  return pitch_.R_belt_sheet() * geometry_.t_scanner_camera_mm + Eigen::Vector3d(0.0, y_mm, 0.0);
}

void LaserLineScanner::probe_top_surface(double y_mm, int first, int end, double top_z_mm,
                                         LaserLine& line) {
  const EmbreeScene& embree = scene_.embree();
  // Down the sheet from its point at in-sheet height top_s_mm: the ray's length is the
  // in-sheet height it descends.
  const double top_s_mm = top_z_mm / pitch_.cos();
  const Eigen::Vector3d top = pitch_.belt_point(0.0, y_mm, top_s_mm);
  const Eigen::Vector3d up = pitch_.up_belt();
  for (int base = first; base < end; base += kPacket) {
    alignas(32) int valid[kPacket];
    RTCRayHit8 packet;
    for (int k = 0; k < kPacket; ++k) {
      const int i = base + k;
      valid[k] = i < end ? -1 : 0;
      packet.ray.org_x[k] = static_cast<float>(line.x_mm(i));
      // Relative to the sheet's foot, so the rays keep their precision wherever the belt is.
      packet.ray.org_y[k] = static_cast<float>(top.y() - y_mm);
      packet.ray.org_z[k] = static_cast<float>(top.z());
      packet.ray.dir_x[k] = 0.0f;
      // 0 − u rather than −u: an unpitched sheet's ray keeps +0 across, not −0, so its
      // traversal (Embree takes 1/dir) is the vertical probe's to the bit.
      packet.ray.dir_y[k] = static_cast<float>(0.0 - up.y());
      packet.ray.dir_z[k] = static_cast<float>(0.0 - up.z());
      packet.ray.tnear[k] = 0.0f;
      packet.ray.tfar[k] = static_cast<float>(top_s_mm - kBeltToleranceMm);
      packet.ray.time[k] = 0.0f;
      packet.ray.mask[k] = 0xFFFFFFFFu;
      packet.ray.id[k] = static_cast<unsigned>(k);
      packet.ray.flags[k] = 0;
    }
    embree.intersect8(valid, packet, y_mm);
    for (int k = 0; k < kPacket && base + k < end; ++k) {
      if (packet.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) continue;
      const auto i = static_cast<std::size_t>(base + k);
      const float z = static_cast<float>(top_s_mm - static_cast<double>(packet.ray.tfar[k]));
      line.z_mm[i] = z;
      Eigen::Vector3d normal =
          embree.world_normal(EmbreeScene::hit_instance(packet.hit, k), packet.hit.Ng_x[k],
                              packet.hit.Ng_y[k], packet.hit.Ng_z[k]);
      // The probe comes from above, so the surface it met faces up the sheet, whatever the
      // winding.
      if (normal.dot(up) < 0.0) normal = -normal;
      normal_x_[i] = static_cast<float>(normal.x());
      normal_y_[i] = static_cast<float>(normal.y());
      normal_z_[i] = static_cast<float>(normal.z());
    }
  }
}

void LaserLineScanner::sweep_laser_horizon(LaserLine& line) const {
  std::fill(line.state.begin(), line.state.end(), LaserSampleState::kMeasured);
  if (parameters_.laser_model == LaserModel::kParallel) return;
  const double source_height_mm = parameters_.laser_height_mm;
  // tan of the fan ray's angle from the vertical; it only grows outward while the ray clears
  // every top point nearer the source.
  const auto visit = [&](int i, double distance_from_source_mm, double& horizon) {
    const double below_source_mm = source_height_mm - line.z_mm[static_cast<std::size_t>(i)];
    if (!(below_source_mm > 0.0)) {
      line.state[static_cast<std::size_t>(i)] = LaserSampleState::kOutOfRange;
      return;
    }
    const double tangent = distance_from_source_mm / below_source_mm;
    if (tangent < horizon) {
      line.state[static_cast<std::size_t>(i)] = LaserSampleState::kLaserShadow;
    } else {
      horizon = tangent;
    }
  };
  // The source hangs over the belt centre, x = 0.
  const int first_right =
      std::clamp(static_cast<int>(std::ceil(-line.x0_mm / line.dx_mm)), 0, samples_);
  double horizon = -std::numeric_limits<double>::infinity();
  for (int i = first_right; i < samples_; ++i) visit(i, line.x_mm(i), horizon);
  horizon = -std::numeric_limits<double>::infinity();
  for (int i = first_right - 1; i >= 0; --i) visit(i, -line.x_mm(i), horizon);
}

LaserLineScanner::LitPoint LaserLineScanner::classify_lit_point(
    const Eigen::Vector3d& point_scanner_mm, const Eigen::Vector3d& normal,
    double cos_incidence) const {
  LitPoint lit;
  if (cos_incidence < cos_max_incidence_) {
    lit.state = LaserSampleState::kGrazing;
    return lit;
  }
  lit.intensity = static_cast<float>(parameters_.reflectivity * cos_incidence);
  Eigen::Vector2d uv;
  if (!geometry_.project_to_image(point_scanner_mm, uv)) {
    lit.state = LaserSampleState::kOutOfRange;
    return lit;
  }
  lit.u_px = static_cast<float>(uv.x());
  lit.v_px = static_cast<float>(uv.y());
  const double sensor_last_column = geometry_.camera.width_px - 1;
  if (!(uv.x() >= 0.0 && uv.x() <= sensor_last_column && uv.y() >= min_roi_row_px_ &&
        uv.y() <= max_roi_row_px_)) {
    lit.state = LaserSampleState::kOutOfRange;
  } else if (normal.dot(geometry_.t_scanner_camera_mm - point_scanner_mm) <= 0.0) {
    lit.state = LaserSampleState::kCameraOccluded;
  }
  return lit;
}

void LaserLineScanner::classify(double y_mm, LaserLine& line) {
  occlusion_candidates_.clear();
  const Eigen::Vector3d source_mm = pitch_.belt_point(0.0, y_mm, parameters_.laser_height_mm);
  const Eigen::Vector3d camera_mm = camera_belt_mm(y_mm);
  const Eigen::Matrix3d R_sheet_belt = pitch_.R_belt_sheet().transpose();
  belt_sights_.clear();
  std::fill(belt_sight_marks_.begin(), belt_sight_marks_.end(), 0);
  // A belt point's line of sight runs from the sheet to the camera: only parts within that
  // stretch of belt can hide it.
  scene_.for_each_part_meeting_y(
      std::min(y_mm, camera_mm.y()), std::max(y_mm, camera_mm.y()), [&](const PlacedPart& part) {
        belt_sights_.push_back({&part, part.height_bounds.belt_sight(y_mm, camera_mm)});
        part.height_bounds.mark_belt_sights(belt_sights_.back().sight, line.x0_mm, line.dx_mm,
                                            samples_, belt_sight_marks_.data());
      });
  int belt_sight_marked = 0;  // running sum of the marks: > 0 where a part may hide the belt
  for (int i = 0; i < samples_; ++i) {
    const auto s = static_cast<std::size_t>(i);
    belt_sight_marked += belt_sight_marks_[s];
    if (line.state[s] != LaserSampleState::kMeasured) {
      line.intensity[s] = 0.0f;
      line.u_px[s] = kNoData;
      line.v_px[s] = kNoData;
      continue;
    }
    const bool on_belt = line.z_mm[s] == 0.0f;
    LitPoint lit = belt_samples_[s];
    if (!on_belt) {
      const Eigen::Vector3d normal(normal_x_[s], normal_y_[s], normal_z_[s]);
      const Eigen::Vector3d point_mm = pitch_.belt_point(line.x_mm(i), y_mm, line.z_mm[s]);
      const double cos_incidence = parameters_.laser_model == LaserModel::kFan
                                       ? -normal.dot((point_mm - source_mm).normalized())
                                       : normal.dot(pitch_.up_belt());
      lit = classify_lit_point(Eigen::Vector3d(line.x_mm(i), 0.0, line.z_mm[s]),
                               R_sheet_belt * normal, cos_incidence);
    }
    line.state[s] = lit.state;
    line.intensity[s] = lit.intensity;
    line.u_px[s] = lit.u_px;
    line.v_px[s] = lit.v_px;
    if (lit.state != LaserSampleState::kMeasured || (on_belt && belt_sight_marked == 0)) continue;
    // A part point lies under its own cell's height bound, so the walk could never clear it.
    if (!on_belt) {
      occlusion_candidates_.push_back(i);
      continue;
    }
    const Eigen::Vector3d point_mm(line.x_mm(i), y_mm, 0.0);
    for (const PartSight& near : belt_sights_) {
      if (!near.part->height_bounds.may_block(near.sight, point_mm.x())) continue;
      if (!near.part->height_bounds.clears(point_mm, camera_mm)) {
        occlusion_candidates_.push_back(i);
        break;
      }
    }
  }
}

void LaserLineScanner::trace_camera_occlusion(double y_mm, LaserLine& line) {
  const Eigen::Vector3d camera_mm = camera_belt_mm(y_mm);
  const int count = static_cast<int>(occlusion_candidates_.size());
  for (int base = 0; base < count; base += kPacket) {
    alignas(32) int valid[kPacket];
    RTCRay8 packet;
    for (int k = 0; k < kPacket; ++k) {
      const bool used = base + k < count;
      valid[k] = used ? -1 : 0;
      const auto s = static_cast<std::size_t>(
          used ? occlusion_candidates_[static_cast<std::size_t>(base + k)] : 0);
      const Eigen::Vector3d normal(normal_x_[s], normal_y_[s], normal_z_[s]);
      const Eigen::Vector3d origin =
          pitch_.belt_point(line.x_mm(static_cast<int>(s)), y_mm, line.z_mm[s]) +
          kSurfaceOffsetMm * normal;
      const Eigen::Vector3d direction = camera_mm - origin;
      packet.org_x[k] = static_cast<float>(origin.x());
      packet.org_y[k] = static_cast<float>(origin.y() - y_mm);  // relative to the sheet's foot
      packet.org_z[k] = static_cast<float>(origin.z());
      packet.dir_x[k] = static_cast<float>(direction.x());
      packet.dir_y[k] = static_cast<float>(direction.y());
      packet.dir_z[k] = static_cast<float>(direction.z());
      packet.tnear[k] = 0.0f;
      packet.tfar[k] = 1.0f;
      packet.time[k] = 0.0f;
      packet.mask[k] = 0xFFFFFFFFu;
      packet.id[k] = static_cast<unsigned>(k);
      packet.flags[k] = 0;
    }
    scene_.embree().occluded8(valid, packet, y_mm);
    for (int k = 0; k < kPacket && base + k < count; ++k) {
      // Embree marks an occluded ray by setting its tfar to -inf.
      if (packet.tfar[k] < 0.0f) {
        line.state[static_cast<std::size_t>(
            occlusion_candidates_[static_cast<std::size_t>(base + k)])] =
            LaserSampleState::kCameraOccluded;
      }
    }
  }
  const auto min_intensity = static_cast<float>(parameters_.min_reflected_intensity);
  for (std::size_t s = 0; s < line.state.size(); ++s) {
    if (line.state[s] == LaserSampleState::kMeasured && line.intensity[s] < min_intensity) {
      line.state[s] = LaserSampleState::kDark;
    }
  }
}

}  // namespace cosmos
