#pragma once
// Curvature-consistency smoothing (§3.5.1; Ferrie, Lagarde & Whaite 1993; Sander & Zucker
// 1990): each iteration re-estimates a pixel's Darboux frame as a robust average of the frames
// its valid same-side 8-neighbours predict for it. A neighbour j predicts, by transporting its
// local quadric to pixel i, the normal n_j + W_j (p_i - p_j) and its own Weingarten tensor
// re-projected onto the new tangent plane. Predictions are weighted by how well they agree
// with pixel i's current frame (Cauchy weights on the normal deviation and on the curvature-
// tensor disagreement relative to the tensors' size, floored at the fit's curvature noise) and
// by the neighbour's reliability (its tilt), so frames are never averaged across creases and
// silhouettes do not bleed inwards, while noise is not taken for a curvature edge.
//
// One iteration of one row reads only rows r-1..r+1 of the previous iteration, so the real-time
// loop can pipeline the iterations row by row. The row kernel is branch-free over a row of
// structure-of-arrays frames, so that it vectorizes across columns.
#include <array>
#include <cstdint>

#include "core/cosmos_parameters.hpp"
#include "core/surface/darboux_frame_field.hpp"

namespace cosmos {

// Rows r-1, r, r+1 (index 0, 1, 2) of the fixed geometry and of the previous iteration's
// frames; at the image border the missing row points at row r (its same-side bits are 0).
struct SmoothingRowInput {
  int width = 0;
  // Only columns [column_begin, column_end) are smoothed (column_end -1: the whole row); the
  // others must be invalid pixels, and keep their frame, as invalid pixels do inside. A
  // caller that knows where the row's valid pixels lie skips the smoothing of the rest.
  int column_begin = 0;
  int column_end = -1;
  // False when the output row already holds the frames outside the range (a caller that
  // passes the same range every time and filled both of its buffers once).
  bool copy_outside_range = true;
  const std::uint8_t* valid = nullptr;
  const std::uint8_t* same_side = nullptr;
  // The grid's spacing: neighbour k lies at (dc dx, dr dy) in the plane, so only the
  // heights of the rows above, at and below are read.
  float pixel_size_x_mm = 0;
  float pixel_size_y_mm = 0;
  const float* z_mm[3] = {};
  const float* frame[3][kFrameComponents] = {};
};

void smooth_frame_row(const SmoothingRowInput& in, float* const* out_frame,
                      const SmoothingParameters& parameters);

// [first, last + 1) of a row's valid pixels ({w, w} or narrower when none): the columns a
// smoothing pass needs to compute.
std::array<int, 2> valid_column_extent(const std::uint8_t* valid, int width);

// Runs parameters.iterations iterations over the whole field in place.
// `field` fitted on a grid of this spacing (its positions x0 + i dx, y0 + j dy).
void smooth_curvatures(DarbouxFrameField& field, double pixel_size_x_mm, double pixel_size_y_mm,
                       const SmoothingParameters& parameters);

}  // namespace cosmos
