#pragma once
// Every parameter of the COSMOS pipeline of one view, with its documented default.
// The defaults are the thesis's where it gives one (5x5 window, 15 smoothing iterations,
// shape diameter 0.25, 15 patches, bin width 0.005). Each struct lists its fields once in
// visit() (core/parameter_visitor.hpp): the model base records them under cosmos.* by it, and
// a cell recognizes with the ones its model base recorded.
#include "core/parameter_visitor.hpp"

namespace cosmos {

struct SurfaceFitParameters {
  int window_size = 5;         // odd; §3.5.1 uses 5x5
  bool bicubic = true;         // bicubic z(x, y) (§3.5.1); false: biquadratic
  double depth_jump_mm = 3.0;  // |dz| per pixel step above which samples lie across an edge
  int min_samples = 12;        // fewer valid same-side samples: the pixel is invalid
  // RMS residual (mm) above which a window is taken to straddle a crease (an orientation
  // discontinuity); the pixel is then fitted from the shifted window, still containing it,
  // that fits best. Well above sensor noise (~0.02 mm); 0 disables.
  double crease_residual_mm = 0.06;

  template <class Visitor>
  void visit(Visitor& v) {
    v("window_size", window_size, "fit window, pixels (odd; §3.5.1: 5)", Range{3, 15});
    v("bicubic", bicubic, "bicubic z(x, y) (§3.5.1); false: biquadratic");
    v("depth_jump_mm", depth_jump_mm,
      "|dz| per pixel step across an edge, mm (fit windows and the live grid's interpolation)",
      Range::above(0, 1e4));
    v("min_samples", min_samples, "fewer valid same-side samples: the pixel is invalid",
      Range{1, 225});
    v("crease_residual_mm", crease_residual_mm,
      "RMS residual of a window straddling a crease, mm; 0: no shifted windows", Range{0, 10});
  }
};

struct SmoothingParameters {
  int iterations = 15;            // §3.5.1: 15 iterations
  double normal_scale_deg = 8.0;  // robust scale of a predicted normal's deviation
  double curvature_scale = 0.5;   // robust scale of relative curvature-tensor disagreement
  double self_weight = 1.0;       // weight of a pixel's own frame among its neighbours'
  // Tensor disagreement is relative to |W_i|^2 + |W_j|^2 + floor^2: below the fit's own
  // curvature noise a disagreement is no evidence of a curvature edge. 0.04/mm is the median
  // |W| the 5x5 fit gives a plane under the cell's noise (0.02 mm on a 0.4 mm grid); at 1e-3
  // noisy low-curvature regions barely smoothed (their neighbours' weights fell below the
  // pixel's own).
  double curvature_floor_per_mm = 0.04;

  template <class Visitor>
  void visit(Visitor& v) {
    v("iterations", iterations, "curvature-consistency iterations (§3.5.1: 15)", Range{0, 1000});
    v("normal_scale_deg", normal_scale_deg, "robust scale of a predicted normal's deviation, deg",
      Range::above(0, 180));
    v("curvature_scale", curvature_scale, "robust scale of relative curvature disagreement",
      Range::above(0, 100));
    v("self_weight", self_weight, "weight of a pixel's own frame among its neighbours'",
      Range{0, 100});
    v("curvature_floor_per_mm", curvature_floor_per_mm,
      "curvature below which a disagreement is fit noise, 1/mm", Range{0, 10});
  }
};

struct ShapeIndexParameters {
  // Eqs. 3.21-3.22: |grad S_I| = 1 / (pi * sqrt(k1^2 + k2^2)). Pixels more sensitive than
  // this (in mm, i.e. S_I per 1/mm) are planar: here curvatures below ~1/157 mm^-1.
  double planar_sensitivity_mm = 50.0;
  double max_tilt_deg = 85.0;  // steeper normals are unreliable (grazing data): excluded

  template <class Visitor>
  void visit(Visitor& v) {
    v("planar_sensitivity_mm", planar_sensitivity_mm,
      "|grad S_I| above which a pixel is planar, mm (Eqs. 3.21-3.22)", Range::above(0, 1e6));
    v("max_tilt_deg", max_tilt_deg, "steeper normals are excluded, deg", Range::above(0, 90));
  }
};

struct SegmentationParameters {
  double shape_diameter_limit = 0.25;  // §3.5.2, used as is when max_patches = 0
  // §5.4.3 adaptive mode: the smallest limit, from adaptive_start_limit up in steps, that
  // leaves at most max_patches patches of at least the minimum area; 0 = fixed limit.
  int max_patches = 15;
  double adaptive_start_limit = 0.05;
  double adaptive_limit_step = 0.025;
  // Above this the patches would mix shape categories (a cap with a saddle); views whose
  // patches are kept apart by planar bands or edges cannot reach max_patches anyway.
  double adaptive_max_limit = 0.5;
  int boundary_refinement_passes = 8;     // §3.5.2 post-processing of boundary pixels (at most)
  double min_patch_area_fraction = 0.03;  // patches below this share of the view fold away
  // Planar pixels join one planar patch only when their normals agree this well, so the faces
  // of a polyhedron meeting at a crease stay separate patches (§3.2.2).
  double planar_crease_deg = 5.0;
  // Growing starts from seeds: connected pixels whose S_I range stays within this
  // (shape_seeds.hpp). Half of adaptive_start_limit: the first growth stage can still join
  // any two seeds that lie within one limit of each other.
  double seed_shape_index_quantum = 0.025;

  template <class Visitor>
  void visit(Visitor& v) {
    v("shape_diameter_limit", shape_diameter_limit,
      "S_I range of one patch (§3.5.2), when max_patches is 0", Range::above(0, 1));
    v("max_patches", max_patches, "adaptive limit's patch budget (§5.4.3); 0: fixed limit",
      Range{0, 10000});
    v("adaptive_start_limit", adaptive_start_limit, "first adaptive limit", Range::above(0, 1));
    v("adaptive_limit_step", adaptive_limit_step, "adaptive limit step", Range::above(0, 1));
    v("adaptive_max_limit", adaptive_max_limit, "largest adaptive limit", Range::above(0, 1));
    v("boundary_refinement_passes", boundary_refinement_passes,
      "boundary post-processing passes, at most (§3.5.2)", Range{0, 1000});
    v("min_patch_area_fraction", min_patch_area_fraction,
      "patches below this share of the view fold away", Range{0, 1});
    v("planar_crease_deg", planar_crease_deg, "normals of one planar patch agree this well, deg",
      Range{0, 180});
    v("seed_shape_index_quantum", seed_shape_index_quantum, "S_I range of a growing seed",
      Range::above(0, 1));
  }
};

struct SpectrumParameters {
  double bin_width = 0.005;  // §3.5.4

  template <class Visitor>
  void visit(Visitor& v) {
    v("bin_width", bin_width, "shape spectrum bin width in S_I (§3.5.4)", Range::above(0, 1));
  }
};

struct CosmosParameters {
  SurfaceFitParameters fit;
  SmoothingParameters smoothing;
  ShapeIndexParameters shape_index;
  SegmentationParameters segmentation;
  SpectrumParameters spectrum;

  template <class Visitor>
  void visit(Visitor& v) {
    v("fit", fit, "local surface fit (§3.5.1)");
    v("smoothing", smoothing, "curvature-consistency smoothing (§3.5.1)");
    v("shape_index", shape_index, "shape index (§3.2.1)");
    v("segmentation", segmentation, "CSMP segmentation (§3.5.2)");
    v("spectrum", spectrum, "shape spectrum (§3.5.4)");
  }
};

}  // namespace cosmos
