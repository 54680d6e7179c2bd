#pragma once
// Shape index (Eq. 3.2), curvedness (Eq. 3.3) and the planar label from the shape-index
// sensitivity (Eqs. 3.21-3.22), per pixel.
#include <cstdint>

#include "core/cosmos_parameters.hpp"
#include "core/pixel_grid.hpp"
#include "core/surface/darboux_frame_field.hpp"

namespace cosmos {

// Symbolic shape index of planar pixels in spectra (§3.2.1, §3.5.4).
inline constexpr float kPlanarShapeIndex = 2.0f;

enum class SurfaceLabel : std::uint8_t { kInvalid = 0, kCurved = 1, kPlanar = 2 };

// Eq. 3.2 with kappa1 >= kappa2 in the convex-positive convention (a sphere seen from outside
// has S_I = 1, a cup 0, a ridge 0.75, a symmetric saddle 0.5).
float shape_index(float kappa1, float kappa2);
// Eq. 3.3, 1/mm.
float curvedness(float kappa1, float kappa2);
// Magnitude of the gradient of S_I w.r.t. (kappa1, kappa2), Eqs. 3.21-3.22, in mm.
float shape_index_sensitivity_mm(float kappa1, float kappa2);

struct ShapeIndexField {
  PixelGrid<SurfaceLabel> label;
  PixelGrid<float> shape_index;  // [0, 1] on curved pixels, 2.0 on planar, NaN invalid
  PixelGrid<float> curvedness_per_mm;
  PixelGrid<float> area_mm2;          // true surface area of the pixel's cell, from its normal
  PixelGrid<std::uint8_t> same_side;  // copied from the frame field: 8-connectivity for growing

  int width() const { return label.width(); }
  int height() const { return label.height(); }
};

// A field of the given size with every pixel invalid.
ShapeIndexField make_shape_index_field(int width, int height);

// Classifies one row of the frame field (the real-time loop calls it row by row).
void classify_row(const DarbouxFrameField& frames, int row, double pixel_size_x_mm,
                  double pixel_size_y_mm, const ShapeIndexParameters& parameters,
                  ShapeIndexField& out);
ShapeIndexField classify_surface(const DarbouxFrameField& frames, double pixel_size_x_mm,
                                 double pixel_size_y_mm, const ShapeIndexParameters& parameters);
// Into a field of the frames' size (every pixel is written).
void classify_surface(const DarbouxFrameField& frames, double pixel_size_x_mm,
                      double pixel_size_y_mm, const ShapeIndexParameters& parameters,
                      ShapeIndexField& field);

}  // namespace cosmos
