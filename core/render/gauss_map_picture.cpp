#include "core/render/gauss_map_picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <set>
#include <string>
#include <unordered_map>

#include "core/render/picture_drawing.hpp"
#include "core/render/shape_category_palette.hpp"

namespace cosmos {
namespace {

using namespace render;

constexpr double kPi = 3.14159265358979323846;
constexpr double kCentrePx = kGaussMapSizePx / 2.0;
// The largest patch gets this disc radius; the disc area scales with the patch area, but tiny
// patches keep a visible minimum.
constexpr double kMaxDiscRadiusPx = 0.14 * kGaussMapRadiusPx;
constexpr double kMinDiscRadiusPx = 5.0;
constexpr int kShift = 4;  // sub-pixel bits for cv::circle/cv::line: smooth, still deterministic

cv::Point fixed_point(const Eigen::Vector2d& position) {
  return {static_cast<int>(std::lround(position.x() * (1 << kShift))),
          static_cast<int>(std::lround(position.y() * (1 << kShift)))};
}
int fixed_length(double length_px) {
  return static_cast<int>(std::lround(length_px * (1 << kShift)));
}

void draw_graticule(cv::Mat& canvas) {
  const cv::Point centre = fixed_point({kCentrePx, kCentrePx});
  const BgrColor faint = rgb(215, 215, 215);
  // Latitude circles every 15 degrees of polar angle from +z: radius R sin(theta).
  for (int degrees = 15; degrees < 90; degrees += 15) {
    const double radius = kGaussMapRadiusPx * std::sin(degrees * kPi / 180);
    cv::circle(canvas, centre, fixed_length(radius), scalar(faint), 1, cv::LINE_AA, kShift);
  }
  // Meridians every 30 degrees of azimuth: straight radii in this projection.
  for (int degrees = 0; degrees < 360; degrees += 30) {
    const double a = degrees * kPi / 180;
    const Eigen::Vector2d rim{kCentrePx + kGaussMapRadiusPx * std::cos(a),
                              kCentrePx + kGaussMapRadiusPx * std::sin(a)};
    cv::line(canvas, centre, fixed_point(rim), scalar(faint), 1, cv::LINE_AA, kShift);
  }
  cv::circle(canvas, centre, fixed_length(kGaussMapRadiusPx), scalar(rgb(120, 120, 120)), 2,
             cv::LINE_AA, kShift);
  // Polar-angle labels along one meridian, away from the axis labels +x and +y.
  for (int degrees : {30, 60}) {
    const double r = kGaussMapRadiusPx * std::sin(degrees * kPi / 180);
    const double a = 120 * kPi / 180;
    draw_text(canvas, std::to_string(degrees) + " deg",
              {static_cast<int>(kCentrePx + r * std::cos(a)) + 4,
               static_cast<int>(kCentrePx + r * std::sin(a)) + 14},
              0.38, rgb(150, 150, 150));
  }
  const int rim_right = static_cast<int>(kCentrePx) + kGaussMapRadiusPx;
  const int rim_bottom = static_cast<int>(kCentrePx) + kGaussMapRadiusPx;
  draw_text(canvas, "+x", {rim_right + 10, static_cast<int>(kCentrePx) + 5}, 0.55);
  draw_text_centred(canvas, "+y", {static_cast<int>(kCentrePx), rim_bottom + 18}, 0.55);
}

double disc_radius_px(double area_mm2, double max_area_mm2) {
  if (!(max_area_mm2 > 0) || !(area_mm2 > 0)) return kMinDiscRadiusPx;
  return std::max(kMinDiscRadiusPx, kMaxDiscRadiusPx * std::sqrt(area_mm2 / max_area_mm2));
}

struct Disc {
  Eigen::Vector2d centre;
  double radius = 0;
};

bool overlaps(const cv::Rect& box, const Disc& disc) {
  const double x = std::clamp(disc.centre.x(), double(box.x), double(box.x + box.width));
  const double y = std::clamp(disc.centre.y(), double(box.y), double(box.y + box.height));
  return (Eigen::Vector2d(x, y) - disc.centre).norm() < disc.radius;
}

// Greedy, deterministic label placement: the first spot around the disc (nearest ring first,
// up-right first) whose text box overlaps no disc and no label placed before; a label pushed
// out beyond the first ring gets a leader line to its disc. Patches of similar orientation (the
// rings of a torus all have G0 near +z) would otherwise stack their ids into one blot.
void draw_patch_label(cv::Mat& canvas, const std::string& text, const Disc& disc,
                      const std::vector<Disc>& discs, std::vector<cv::Rect>& placed) {
  constexpr double kFontScale = 0.5;
  constexpr int kThickness = 2;
  constexpr int kRings = 10;
  const Eigen::Vector2d& at = disc.centre;
  const double radius = disc.radius;
  constexpr std::array<int, 8> kAnglesDeg{-45, -135, 45, 135, 0, 180, -90, 90};
  const cv::Size size = text_extent(text, kFontScale, kThickness);
  const auto box_at = [&](const cv::Point& centre) {
    return cv::Rect(centre.x - size.width / 2 - 2, centre.y - size.height / 2 - 3, size.width + 4,
                    size.height + 6);
  };
  cv::Point chosen;
  int chosen_ring = -1;
  for (int ring = 0; ring < kRings && chosen_ring < 0; ++ring) {
    for (int degrees : kAnglesDeg) {
      const double a = degrees * kPi / 180;
      const double distance = radius + 10 + 16.0 * ring;
      const cv::Point centre{static_cast<int>(std::lround(at.x() + distance * std::cos(a))),
                             static_cast<int>(std::lround(at.y() + distance * std::sin(a)))};
      const cv::Rect box = box_at(centre);
      const bool free =
          std::none_of(placed.begin(), placed.end(),
                       [&](const cv::Rect& other) { return (box & other).area() > 0; }) &&
          std::none_of(discs.begin(), discs.end(),
                       [&](const Disc& other) { return overlaps(box, other); });
      if (free) {
        chosen = centre;
        chosen_ring = ring;
        break;
      }
    }
  }
  if (chosen_ring < 0) {
    chosen = {static_cast<int>(std::lround(at.x() + (radius + 10) * 0.7071)),
              static_cast<int>(std::lround(at.y() - (radius + 10) * 0.7071))};
  }
  if (chosen_ring > 0) {
    const Eigen::Vector2d towards = Eigen::Vector2d(chosen.x, chosen.y) - at;
    const Eigen::Vector2d edge = at + towards.normalized() * radius;
    const Eigen::Vector2d end = at + towards.normalized() * (towards.norm() - 8);
    cv::line(canvas, fixed_point(edge), fixed_point(end), scalar(rgb(120, 120, 120)), 1,
             cv::LINE_AA, kShift);
  }
  placed.push_back(box_at(chosen));
  draw_text_centred(canvas, text, chosen, kFontScale, kInk, kThickness);
}

}  // namespace

Eigen::Vector2d gauss_map_position_px(const Eigen::Vector3d& normal) {
  return {kCentrePx + kGaussMapRadiusPx * normal.x(), kCentrePx + kGaussMapRadiusPx * normal.y()};
}

BgrPicture render_gauss_map_picture(const CosmosView& view) {
  cv::Mat canvas = blank_canvas(kGaussMapSizePx, kGaussMapSizePx);
  draw_graticule(canvas);
  draw_text(canvas, "Gauss patch map, seen from +z", {12, 24}, 0.6);
  draw_text(canvas, "disc area ~ patch area; lines: adjacent patches", {12, kGaussMapSizePx - 14},
            0.45, rgb(90, 90, 90));

  const std::vector<Csmp>& patches = view.patches;
  std::unordered_map<int, std::size_t> index_of_id;
  double max_area_mm2 = 0;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    index_of_id.emplace(patches[i].id, i);
    max_area_mm2 = std::max(max_area_mm2, patches[i].area_mm2);
  }
  const auto position = [&](const Csmp& patch) {
    const Eigen::Vector3d n =
        patch.mean_normal.allFinite() ? patch.mean_normal : Eigen::Vector3d::UnitZ();
    return gauss_map_position_px(n);
  };

  // Each adjacent pair once, even if only one side lists the other: anti-aliased lines drawn
  // twice would come out darker.
  std::set<std::pair<int, int>> adjacent_ids;
  for (const Csmp& patch : patches) {
    for (const PatchNeighbor& neighbor : patch.neighbors) {
      if (neighbor.patch == patch.id || !index_of_id.contains(neighbor.patch)) continue;
      adjacent_ids.emplace(std::min(patch.id, neighbor.patch), std::max(patch.id, neighbor.patch));
    }
  }
  for (const auto& [a, b] : adjacent_ids) {
    cv::line(canvas, fixed_point(position(patches[index_of_id.at(a)])),
             fixed_point(position(patches[index_of_id.at(b)])), scalar(rgb(70, 70, 70)), 1,
             cv::LINE_AA, kShift);
  }

  // Large discs first, so that small patches sharing an orientation stay visible on top.
  std::vector<std::size_t> order(patches.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return patches[a].area_mm2 > patches[b].area_mm2;
  });
  for (std::size_t i : order) {
    const Csmp& patch = patches[i];
    const Eigen::Vector2d at = position(patch);
    const double radius = disc_radius_px(patch.area_mm2, max_area_mm2);
    // A G0 facing away from the sensor lies on the far hemisphere: drawn hollow.
    const bool far_side = patch.mean_normal.z() < 0;
    cv::circle(canvas, fixed_point(at), fixed_length(radius), scalar(patch_color(patch.id)),
               far_side ? 2 : cv::FILLED, cv::LINE_AA, kShift);
    cv::circle(canvas, fixed_point(at), fixed_length(radius), scalar(kInk), 1, cv::LINE_AA, kShift);
  }
  // Labels last, beside their discs so that the disc colours stay unobstructed.
  std::vector<Disc> discs;
  for (const Csmp& patch : patches)
    discs.push_back({position(patch), disc_radius_px(patch.area_mm2, max_area_mm2)});
  std::vector<cv::Rect> placed;
  for (std::size_t i : order)
    draw_patch_label(canvas, std::to_string(patches[i].id), discs[i], discs, placed);
  return to_picture(canvas);
}

}  // namespace cosmos
