#pragma once
// A laser sheet pitched against the belt: turned about the belt's x axis (across the belt)
// so that it leans downstream (+y, the direction of travel) with height by pitch_deg. A
// point the sheet lights at in-sheet height s (what the triangulation in the sheet's own
// frame measures) lies s · sin(pitch) downstream of the sheet's foot on the belt and
// s · cos(pitch) above the belt. The sheet frame (x across, y the sheet's normal, z up the
// sheet) is the belt frame turned by the pitch; at pitch 0 the two are one and every
// conversion below is exact.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace cosmos {

class SheetPitch {
 public:
  SheetPitch() = default;
  explicit SheetPitch(double pitch_deg)
      : sin_(std::sin(pitch_deg * std::numbers::pi / 180.0)),
        cos_(std::cos(pitch_deg * std::numbers::pi / 180.0)) {}

  double sin() const { return sin_; }
  double cos() const { return cos_; }
  bool pitched() const { return sin_ != 0.0; }

  // The sheet's up direction in the belt frame.
  Eigen::Vector3d up_belt() const { return {0.0, sin_, cos_}; }
  // Columns: the sheet frame's axes in the belt frame (v_belt = R · v_sheet).
  Eigen::Matrix3d R_belt_sheet() const {
    Eigen::Matrix3d r;
    r << 1.0, 0.0, 0.0, 0.0, cos_, sin_, 0.0, -sin_, cos_;
    return r;
  }
  // The belt-frame point at in-sheet height s above the sheet's foot (x, foot_y_mm, 0).
  Eigen::Vector3d belt_point(double x_mm, double foot_y_mm, double s_mm) const {
    return {x_mm, foot_y_mm + s_mm * sin_, s_mm * cos_};
  }

 private:
  double sin_ = 0.0;
  double cos_ = 1.0;
};

}  // namespace cosmos
