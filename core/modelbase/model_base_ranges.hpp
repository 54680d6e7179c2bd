#pragma once
// The semantic checks of a model base read from a file: the FlatBuffers verifier proves only
// that every offset and length stays inside the buffer, not that a value makes sense. A file
// written by a buggy builder or crafted by hand, with its checksum recomputed, can hold
// coordinates of 1e300 mm or NaN, which the recognizer trusts: the pose search's distance
// field (core/registration/part_distance_field.hpp) spans every point of a part's views, so
// one absurd point asked it for an unbounded grid. Every number the recognizer uses is
// checked here against a range no real base leaves.
//
// The bounds are generous: parts of a work cell are at most metres, the scanner's grid
// spacing at most millimetres.
#include <optional>
#include <string>

#include "core/modelbase/model_base.hpp"

namespace cosmos {

struct ModelBaseRanges {
  double max_coordinate_mm = 1e4;  // any position, translation, size, centroid
  double max_spacing_mm = 100.0;   // the registration grid's cell size
  int max_grid_cells_per_side = 1 << 16;
  // A view's whole grid (an unpacked view holds an index per cell): 16 Mi cells is a 640-pixel
  // profile over 10 m of belt at stride 1.
  double max_grid_cells = 1 << 24;
  double max_unit_vector_error = 1e-3;  // directions and normals: |norm - 1|
  double max_rotation_error = 1e-6;     // |R^T R - I|, element-wise
};

// The first value out of range, as "view 12: registration origin_x_mm is 1e+300, expected
// within +-10000", or nullopt when every value is in range.
std::optional<std::string> model_base_out_of_range(const ModelBase& base,
                                                   const ModelBaseRanges& ranges = {});

}  // namespace cosmos
