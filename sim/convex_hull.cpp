#include "sim/convex_hull.hpp"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace cosmos {
namespace {

// Qhull's state and memory for one run, released on every path out.
class QhullRun {
 public:
  QhullRun() {
    // Qhull reports problems to a FILE; the reason is thrown instead, so its text goes nowhere.
    sink_ = std::fopen("/dev/null", "w");
    qh_zero(&qh_, sink_);
  }
  ~QhullRun() {
    qh_freeqhull(&qh_, !qh_ALL);
    int current_long = 0;
    int total_long = 0;
    qh_memfreeshort(&qh_, &current_long, &total_long);
    if (sink_ != nullptr) std::fclose(sink_);
  }
  QhullRun(const QhullRun&) = delete;
  QhullRun& operator=(const QhullRun&) = delete;

  int run(std::vector<coordT>& coordinates) {
    char command[] = "qhull";
    return qh_new_qhull(&qh_, 3, static_cast<int>(coordinates.size() / 3), coordinates.data(),
                        False, command, nullptr, sink_);
  }
  qhT* get() { return &qh_; }

 private:
  qhT qh_;
  FILE* sink_ = nullptr;
};

// Qhull lists a merged face's vertices unordered; order them by angle around the face's mean.
// Each angle is computed once: re-evaluating it inside the comparator may round differently
// (fused multiply-add) and flip a corner opposite the first between +pi and -pi, which makes
// the ordering inconsistent.
void order_corners(HullFace& face) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& corner : face.corners) mean += corner;
  mean /= static_cast<double>(face.corners.size());
  const Eigen::Vector3d axis_u = (face.corners.front() - mean).normalized();
  const Eigen::Vector3d axis_v = face.normal.cross(axis_u);
  std::vector<std::pair<double, Eigen::Vector3d>> by_angle;
  by_angle.reserve(face.corners.size());
  for (const Eigen::Vector3d& corner : face.corners) {
    by_angle.emplace_back(std::atan2((corner - mean).dot(axis_v), (corner - mean).dot(axis_u)),
                          corner);
  }
  std::sort(by_angle.begin(), by_angle.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t k = 0; k < by_angle.size(); ++k) face.corners[k] = by_angle[k].second;
}

}  // namespace

ConvexHull convex_hull(const std::vector<Eigen::Vector3f>& points) {
  if (points.size() < 4) throw std::invalid_argument("convex_hull: fewer than 4 points");
  std::vector<coordT> coordinates;
  coordinates.reserve(points.size() * 3);
  for (const Eigen::Vector3f& p : points) {
    for (int k = 0; k < 3; ++k) coordinates.push_back(p(k));
  }
  QhullRun run;
  if (run.run(coordinates) != 0)
    throw std::invalid_argument("convex_hull: the points span no volume");
  qhT* qh = run.get();
  ConvexHull hull;
  facetT* facet = nullptr;
  FORALLfacets {
    HullFace face;
    face.normal = Eigen::Vector3d(facet->normal[0], facet->normal[1], facet->normal[2]);
    face.offset = facet->offset;
    vertexT* vertex = nullptr;
    vertexT** vertexp = nullptr;
    FOREACHvertex_(facet->vertices) {
      face.corners.emplace_back(vertex->point[0], vertex->point[1], vertex->point[2]);
    }
    order_corners(face);
    hull.faces.push_back(std::move(face));
  }
  // Volume and centroid from tetrahedra fanned from an interior point.
  Eigen::Vector3d inside = Eigen::Vector3d::Zero();
  for (const HullFace& face : hull.faces) inside += face.corners.front();
  inside /= static_cast<double>(hull.faces.size());
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const HullFace& face : hull.faces) {
    for (std::size_t k = 1; k + 1 < face.corners.size(); ++k) {
      const Eigen::Vector3d& a = face.corners[0];
      const Eigen::Vector3d& b = face.corners[k];
      const Eigen::Vector3d& c = face.corners[k + 1];
      const double volume = std::abs((a - inside).dot((b - inside).cross(c - inside))) / 6.0;
      hull.volume += volume;
      moment += volume * (inside + a + b + c) / 4.0;
    }
  }
  if (!(hull.volume > 0.0)) throw std::invalid_argument("convex_hull: the points span no volume");
  hull.centroid = moment / hull.volume;
  return hull;
}

bool projects_inside(const HullFace& face, const Eigen::Vector3d& point, double margin) {
  const Eigen::Vector3d projected = point - (face.normal.dot(point) + face.offset) * face.normal;
  const std::size_t n = face.corners.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d& a = face.corners[k];
    const Eigen::Vector3d& b = face.corners[(k + 1) % n];
    // Inward edge normal in the face plane (corners run counter-clockwise about the normal).
    const Eigen::Vector3d inward = face.normal.cross(b - a).normalized();
    if (inward.dot(projected - a) < margin) return false;
  }
  return true;
}

double solid_angle(const HullFace& face, const Eigen::Vector3d& point) {
  // Van Oosterom and Strackee (1983), summed over a fan of the convex face.
  double total = 0.0;
  for (std::size_t k = 1; k + 1 < face.corners.size(); ++k) {
    const Eigen::Vector3d a = face.corners[0] - point;
    const Eigen::Vector3d b = face.corners[k] - point;
    const Eigen::Vector3d c = face.corners[k + 1] - point;
    const double la = a.norm();
    const double lb = b.norm();
    const double lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    total += std::abs(2.0 * std::atan2(numerator, denominator));
  }
  return total;
}

}  // namespace cosmos
