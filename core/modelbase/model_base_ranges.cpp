#include "core/modelbase/model_base_ranges.hpp"

#include <cmath>
#include <sstream>

namespace cosmos {
namespace {

// Collects the first value out of range; later checks are skipped once one is found.
class RangeCheck {
 public:
  explicit RangeCheck(const ModelBaseRanges& ranges) : ranges_(ranges) {}

  bool failed() const { return reason_.has_value(); }
  std::optional<std::string> reason() const { return reason_; }
  const ModelBaseRanges& ranges() const { return ranges_; }

  void finite(const std::string& where, const std::string& name, double value) {
    if (!failed() && !std::isfinite(value)) fail(where, name, value, "a finite number");
  }
  void within(const std::string& where, const std::string& name, double value, double limit) {
    if (!failed() && !(std::abs(value) <= limit))
      fail(where, name, value, "within +-" + number(limit));
  }
  void between(const std::string& where, const std::string& name, double value, double low,
               double high) {
    if (!failed() && !(value >= low && value <= high))
      fail(where, name, value, "in [" + number(low) + ", " + number(high) + "]");
  }
  void coordinates(const std::string& where, const std::string& name, const Eigen::Vector3d& v) {
    for (int axis = 0; axis < 3; ++axis)
      within(where, name + "." + "xyz"[axis], v[axis], ranges_.max_coordinate_mm);
  }
  void finite_vector(const std::string& where, const std::string& name, const Eigen::Vector3d& v) {
    for (int axis = 0; axis < 3; ++axis) finite(where, name + "." + "xyz"[axis], v[axis]);
  }
  void unit_vector(const std::string& where, const std::string& name, const Eigen::Vector3d& v) {
    finite_vector(where, name, v);
    if (!failed() && !(std::abs(v.norm() - 1.0) <= ranges_.max_unit_vector_error))
      fail(where, name + " length", v.norm(), "1");
  }
  void rigid(const std::string& where, const std::string& name, const RigidTransform& T) {
    for (int k = 0; k < 9; ++k) finite(where, name + " rotation", T.rotation(k / 3, k % 3));
    if (failed()) return;
    const double error =
        (T.rotation.transpose() * T.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(error <= ranges_.max_rotation_error))
      fail(where, name + " rotation's |R^T R - I|", error, "a rotation");
    coordinates(where, name + " translation_mm", T.translation_mm);
  }
  void cumulative(const std::string& where, const std::string& name,
                  const ViewSignature& signature) {
    if (!failed() && !is_cumulative(signature))
      reason_ = where + ": " + name + " is not three cumulative distributions, each ending at " +
                number(ViewSignature::kWhole);
  }

 private:
  static std::string number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
  }
  void fail(const std::string& where, const std::string& name, double value,
            const std::string& expected) {
    reason_ = where + ": " + name + " is " + number(value) + ", expected " + expected;
  }

  const ModelBaseRanges& ranges_;
  std::optional<std::string> reason_;
};

void check_cosmos(RangeCheck& check, const std::string& where, const CosmosView& cosmos) {
  check.between(where, "visible_area_mm2", cosmos.visible_area_mm2, 0, 1e12);
  for (std::size_t p = 0; p < cosmos.patches.size() && !check.failed(); ++p) {
    const Csmp& patch = cosmos.patches[p];
    const std::string name = "patch " + std::to_string(p) + " ";
    check.between(where, name + "area_mm2", patch.area_mm2, 0, 1e12);
    check.finite_vector(where, name + "mean_normal", patch.mean_normal);
    check.finite(where, name + "shape_index", patch.shape_index);
    check.finite(where, name + "shape_index_min", patch.shape_index_min);
    check.finite(where, name + "shape_index_max", patch.shape_index_max);
    check.finite(where, name + "mean_curvedness_per_mm", patch.mean_curvedness_per_mm);
    check.coordinates(where, name + "centroid_mm", patch.centroid_mm);
  }
  for (std::size_t g = 0; g < cosmos.gauss_map.size() && !check.failed(); ++g) {
    const GaussMapPoint& point = cosmos.gauss_map[g];
    const std::string name = "Gauss-map point " + std::to_string(g) + " ";
    check.finite_vector(where, name + "direction", point.direction);
    for (const SupportTerm& term : point.terms) {
      check.finite(where, name + "shape_index", term.shape_index);
      check.between(where, name + "area_mm2", term.area_mm2, 0, 1e12);
      check.finite(where, name + "curvedness_area", term.curvedness_area);
    }
  }
}

// The registration points' positions are the grid's cell centres and the stored heights
// (packed_registration_points.hpp): bounding the grid and the heights bounds every point.
// Every coefficient a view's streams decode to is clamped into its [low, high] x step, so
// checking those bounds checks every value the streams can hold, whatever their bits.
void check_registration(RangeCheck& check, const std::string& where,
                        const PackedRegistrationPoints& packed) {
  const ModelBaseRanges& ranges = check.ranges();
  check.between(where, "registration grid_width", packed.grid_width, 0,
                ranges.max_grid_cells_per_side);
  check.between(where, "registration grid_height", packed.grid_height, 0,
                ranges.max_grid_cells_per_side);
  check.between(where, "registration grid cells",
                static_cast<double>(packed.grid_width) * packed.grid_height, 0,
                ranges.max_grid_cells);
  check.within(where, "registration origin_x_mm", packed.origin_x_mm, ranges.max_coordinate_mm);
  check.within(where, "registration origin_y_mm", packed.origin_y_mm, ranges.max_coordinate_mm);
  check.between(where, "registration spacing_x_mm", packed.spacing_x_mm, 1e-6,
                ranges.max_spacing_mm);
  check.between(where, "registration spacing_y_mm", packed.spacing_y_mm, 1e-6,
                ranges.max_spacing_mm);
  check.within(where, "registration grid extent in x (mm)", packed.spacing_x_mm * packed.grid_width,
               ranges.max_coordinate_mm);
  check.within(where, "registration grid extent in y (mm)",
               packed.spacing_y_mm * packed.grid_height, ranges.max_coordinate_mm);
  check.between(where, "registration z_noise_sigma_mm", packed.z_noise_sigma_mm, 0, 1e3);
  for (Eigen::Index k = 0; k < packed.fit_cofactor.size() && !check.failed(); ++k)
    check.finite(where, "registration fit_cofactor", packed.fit_cofactor.data()[k]);
  static constexpr const char* kNames[kSurfaceCoefficients] = {
      "height_mm", "slope x", "slope y", "curvature xx", "curvature xy", "curvature yy"};
  for (int c = 0; c < kSurfaceCoefficients && !check.failed(); ++c) {
    const CoefficientCoding& coding = packed.coefficients[static_cast<std::size_t>(c)];
    const std::string name = std::string("registration ") + kNames[c];
    check.between(where, name + " step", coding.step, 0, ranges.max_coordinate_mm);
    const double low = coding.low * coding.step, high = coding.high * coding.step;
    if (c == kHeight) {
      check.within(where, name + " lower bound", low, ranges.max_coordinate_mm);
      check.within(where, name + " upper bound", high, ranges.max_coordinate_mm);
    } else {
      check.finite(where, name + " lower bound", low);
      check.finite(where, name + " upper bound", high);
    }
  }
}

// The grid's size and its runs are checked where it is read (part_surface_voxels_consistent);
// here where it lies: every voxel centre within the coordinate bound.
void check_surface_voxels(RangeCheck& check, const std::string& where,
                          const PartSurfaceVoxels& voxels) {
  if (voxels.empty()) return;
  const ModelBaseRanges& ranges = check.ranges();
  check.coordinates(where, "surface voxels origin_mm", voxels.origin_mm);
  check.between(where, "surface voxel_mm", voxels.voxel_mm, 1e-6, ranges.max_spacing_mm);
  const Eigen::Vector3d far_corner_mm =
      voxels.origin_mm +
      voxels.voxel_mm * Eigen::Vector3d(voxels.size[0], voxels.size[1], voxels.size[2]);
  check.coordinates(where, "surface voxels far corner", far_corner_mm);
}

void check_moments(RangeCheck& check, const std::string& where, const MomentVector& moments) {
  for (std::size_t m = 0; m < moments.size(); ++m)
    check.finite(where, "moment " + std::to_string(m + 1), moments[m]);
}

}  // namespace

std::optional<std::string> model_base_out_of_range(const ModelBase& base,
                                                   const ModelBaseRanges& ranges) {
  RangeCheck check(ranges);
  for (std::size_t p = 0; p < base.parts.size() && !check.failed(); ++p) {
    const std::string where = "part " + std::to_string(p);
    check.between(where, "size_mm", base.parts[p].size_mm, 0, ranges.max_coordinate_mm);
    check.between(where, "diameter_mm", base.parts[p].diameter_mm, 0, ranges.max_coordinate_mm);
    for (std::size_t r = 0; r < base.parts[p].resting_poses.size(); ++r) {
      const RestingPose& pose = base.parts[p].resting_poses[r];
      const std::string pose_where = where + " resting pose " + std::to_string(r);
      check.rigid(pose_where, "R_belt_part", {pose.R_belt_part, Eigen::Vector3d::Zero()});
      check.between(pose_where, "height_mm", pose.height_mm, 0, ranges.max_coordinate_mm);
      check.between(pose_where, "probability", pose.probability, 0, 1);
    }
    for (std::size_t k = 0; k < base.parts[p].hull_vertices_mm.size(); ++k)
      check.coordinates(where, "hull vertex " + std::to_string(k),
                        base.parts[p].hull_vertices_mm[k]);
    check_surface_voxels(check, where, base.parts[p].surface_voxels);
    for (std::size_t k = 0; k < base.parts[p].surface_sample_mm.size(); ++k)
      check.coordinates(where, "surface sample point " + std::to_string(k),
                        base.parts[p].surface_sample_mm[k]);
  }
  for (std::size_t v = 0; v < base.views.size() && !check.failed(); ++v) {
    const ModelBaseView& view = base.views[v];
    const std::string where = "view " + std::to_string(v);
    check.between(where, "view_index", view.view_index, 0, 1 << 20);
    check.unit_vector(where, "direction_part", view.direction_part);
    check.rigid(where, "T_scanner_part", view.T_scanner_part);
    check_cosmos(check, where, view.cosmos);
    check_moments(check, where, view.moments);
    check_registration(check, where, view.registration_packed);
    check.coordinates(where, "control_point_centroid_mm", view.control_point_centroid_mm);
    const auto length_or_unbounded = [&](const std::string& name, double value_mm) {
      if (!std::isinf(value_mm))
        check.between(where, name, value_mm, 0, check.ranges().max_coordinate_mm);
    };
    length_or_unbounded("extent.highest_mm", view.extent.highest_mm);
    length_or_unbounded("extent.widest_mm", view.extent.widest_mm);
    length_or_unbounded("extent.narrowest_mm", view.extent.narrowest_mm);
    check.cumulative(where, "signature", view.signature);
  }
  for (std::size_t c = 0; c < base.clusters.size() && !check.failed(); ++c)
    check_moments(check, "cluster " + std::to_string(c), base.clusters[c].centroid);
  return check.reason();
}

}  // namespace cosmos
