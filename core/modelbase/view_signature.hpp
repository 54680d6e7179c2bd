#pragma once
// A view's metric signature: three distributions of its control points that stay the same as
// the part turns about the viewing direction and slides on the belt, in millimetres, unlike the
// scale-free shape spectrum (§4.2: the moments of the shape index over the view's surface):
//
//   height  each point's height above the part's lowest point, which is where the belt is
//   radius  each point's distance from the vertical axis through the points' centroid
//   span    the distance between each two points of an even subset of them (at most kSpanPoints)
//
// A scan of one part and that part's view nearest its pose have nearly the same three
// distributions; a part of another shape or another size has other ones. Two signatures are
// compared by the earth mover's distance of each distribution, which for distributions on a
// line is the area between their cumulative fractions: how far, in mm, the one's points would
// have to move to make the other. A search over a large catalog ranks its parts by the closest
// of their views (core/recognition/signature_rank.hpp) before it fits any.
//
// The points are control points (registration_points.hpp), one per grid cell of the range
// image, so each stands for a like piece of the view's projected area, in a model view as in a
// scan: the distributions are alike without any weighting.
#include <Eigen/Core>
#include <array>
#include <cstdint>

namespace cosmos {

struct ModelBase;

struct ViewSignature {
  static constexpr double kBinMm = 4.0;
  static constexpr int kHeightBins = 40;
  static constexpr int kRadiusBins = 50;
  static constexpr int kSpanBins = 80;
  static constexpr int kBins = kHeightBins + kRadiusBins + kSpanBins;
  static constexpr int kSpanPoints = 100;
  // A cumulative fraction of kWhole is every point (a view without points has only zeros).
  static constexpr std::uint16_t kWhole = 65535;

  // The three cumulative distributions, height bins first, then radius and span bins: entry k
  // of each is the fraction of points (or pairs) within (k + 1) * kBinMm, the last one holding
  // every point beyond as well.
  std::array<std::uint16_t, kBins> cumulative{};

  bool empty() const { return cumulative.back() == 0; }
};

// The signature of control points (columns: x, y and height, mm), their heights taken above
// base_height_mm: the belt for a scan, the part's lowest point for a model view.
ViewSignature view_signature(const Eigen::Matrix3Xd& positions_mm, double base_height_mm);

// The sum of the three distributions' earth mover's distances, mm; infinite when either is
// empty.
double signature_distance_mm(const ViewSignature& a, const ViewSignature& b);

// True when each distribution is cumulative (never falling) and ends with every point, or the
// whole signature is empty: what a model base read from a file must hold.
bool is_cumulative(const ViewSignature& signature);

// Every view of the part with control points gets its signature, heights above the part's
// lowest hull corner seen from it. Parts are independent: a builder may summarize them on
// several threads.
void summarize_view_signatures(ModelBase& base, int part);

}  // namespace cosmos
