#pragma once
// How the scanner's profiles become the COSMOS grid (config/cell.yaml, section
// `conditioning:`; realtime/loop/profile_conditioner.hpp does it to live profiles). Declared
// beside the scanner because the model-base build needs it too: the model views are cut from
// the belt at the same height threshold as live scans, and the base records that threshold and
// its views' grid, which a cell's conditioning must match.
#include "core/parameter_visitor.hpp"

namespace cosmos {

struct ConditioningParameters {
  double grid_mm = 0.4;  // COSMOS grid along x (and the belt step along y)
  // The grid covers [x_min, x_max) across the belt; the defaults put its points on the
  // default scanner's samples (config/cell.yaml says why that matters).
  double x_min_mm = -127.8;
  double x_max_mm = 128.2;
  double belt_height_mm = 0.0;  // the belt plane z = belt_height + belt_slope_x * x
  double belt_slope_x = 0.0;
  // Above the belt: part; below: background. The one belt threshold of live scans and of the
  // model views (the model-base build scans them with it).
  double height_threshold_mm = 0.5;
  // The depth jump across which samples are never interpolated is not a parameter of the
  // conditioning: it is the COSMOS fit's (cosmos.fit.depth_jump_mm, recorded in the model
  // base), given to the ProfileConditioner beside these.

  // The live scanner's laser sheet, tilted about x by this angle from the belt normal: a
  // sample at in-sheet height s lies s·sin p along the belt from the sheet's foot, so the
  // rows are de-sheared (realtime/loop/sheet_deshear.hpp). It describes the live scanner only:
  // the model views are rendered with an upright sheet, and the model base does not record it.
  double sheet_pitch_deg = 0.0;
  // The tallest surface the de-shear reaches: its window, and so the rows it delays the loop
  // by, grows with it. Higher samples are dropped (no data) and counted.
  double max_height_mm = 200.0;

  template <class Visitor>
  void visit(Visitor& v) {
    v("grid_mm", grid_mm, "COSMOS grid pitch across the belt and belt travel per profile, mm",
      Range::above(0, 100));
    v("x_min_mm", x_min_mm, "the grid covers [x_min_mm, x_max_mm) across the belt, mm",
      Range{-1e5, 1e5});
    v("x_max_mm", x_max_mm, "end of the grid across the belt, mm", Range{-1e5, 1e5});
    v("belt_height_mm", belt_height_mm,
      "belt plane z = belt_height_mm + belt_slope_x * x, removed, mm", Range{-1e4, 1e4});
    v("belt_slope_x", belt_slope_x, "belt plane slope across the belt", Range{-10, 10});
    v("height_threshold_mm", height_threshold_mm,
      "less above the belt is background, mm (live scans and model views)", Range{0, 1e4});
    v("sheet_pitch_deg", sheet_pitch_deg,
      "laser sheet's tilt along the travel from the belt normal, deg (positive: leaning "
      "downstream with height); rows are de-sheared by height * tan, 0: off",
      Range{-10, 10});
    v("max_height_mm", max_height_mm,
      "tallest surface the de-shear reaches; it delays the rows by ceil(max_height_mm * "
      "|tan(sheet_pitch_deg)| / grid_mm + 1/2), higher samples are dropped (no data) and "
      "counted, mm",
      Range::above(0, 1e4));
    v.retired("depth_jump_mm",
              "cosmos.fit.depth_jump_mm, which the cell takes from its model base");
  }
};

}  // namespace cosmos
