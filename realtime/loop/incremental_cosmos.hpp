#pragma once
// The chapter-3 pipeline of one part, advanced one row at a time as its profiles arrive: the
// local surface fit of row r once rows up to r + h exist, its same-side links, then the 15
// curvature-consistency iterations pipelined row by row (iteration k of row r needs
// iteration k-1 of rows r-1..r+1 only, kept in three-row rings), shape index, curvedness and
// planar label. The same row kernels as whole-image processing (core/), applied in the same
// arithmetic order, so the fields equal analyze_view()'s of the part's rows bit for bit; the
// recognizer worker ends the pipeline with finish_view_analysis() on the part's own pixels
// (the spectrum is not accumulated here: a builder's rows also hold other parts' pixels).
//
// Every buffer is sized at construction from the maxima (width, rows): adding a row never
// allocates.
#include <array>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/range_image.hpp"
#include "core/surface/curvature_consistency.hpp"
#include "core/surface/darboux_frame_field.hpp"
#include "core/surface/local_surface_fit.hpp"
#include "core/surface/shape_index.hpp"

namespace cosmos {

class IncrementalCosmos {
 public:
  IncrementalCosmos(const CosmosParameters& parameters, int width, int max_rows,
                    double pixel_size_x_mm, double pixel_size_y_mm);

  void begin_part(double origin_x_mm, double origin_y_mm);
  // Appends one row of `width` heights (mm, NaN = no data); false when the part is longer
  // than max_rows (the row is dropped).
  bool add_row(const float* z_mm);
  // Runs the pipeline to the last row (the bottom border of the part).
  void finish();

  int rows() const { return rows_; }
  const RangeImage& image() const { return image_; }           // max_rows tall
  const DarbouxFrameField& frames() const { return frames_; }  // smoothed frames
  const ShapeIndexField& field() const { return field_; }

 private:
  // Rows below a pixel that its fit may read: a whole window, since a crease window is
  // shifted by up to half of one (local_surface_fit.hpp). A row is fitted only once they
  // have arrived, so it never reads a row of an earlier part.
  int fit_reach_rows() const { return 2 * (parameters_.fit.window_size / 2); }
  bool advance_one_row_each();
  bool fit_next();
  bool link_next();
  bool smooth_next(int level);
  bool classify_next();
  // Frame rows of smoothing level `level` (0 = fitted, iterations = final), row clamped to
  // the part's rows as whole-image processing does.
  const float* frame_row(int level, int component, int row) const;
  float* writable_frame_row(int level, int component, int row);

  CosmosParameters parameters_;
  int width_;
  int max_rows_;
  LocalSurfaceFitter fitter_;
  RangeImage image_;
  DarbouxFrameField fitted_;  // level 0, plus positions, validity and links of every row
  DarbouxFrameField frames_;  // the last level
  std::vector<std::vector<float>> rings_;  // levels 1 .. iterations-1: 3 rows x components
  ShapeIndexField field_;

  int rows_ = 0;
  bool finished_ = false;
  int fitted_rows_ = 0;
  int linked_rows_ = 0;
  std::vector<int> smoothed_rows_;  // per level 1 .. iterations
  // Per row: the columns smoothing writes, [begin, end) (smooth_next).
  std::vector<std::array<int, 2>> smoothed_columns_;
  int classified_rows_ = 0;
};

}  // namespace cosmos
