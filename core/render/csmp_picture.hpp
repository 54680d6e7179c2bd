#pragma once
// csmps.png: every constant-shape maximal patch (§3.5.2) in its own colour (patch_color of its
// id), the boundaries between two patches dark, each patch's id at its pixel centroid, pixels
// of no patch black. The field is placed by field_layout() of the label image.
#include <vector>

#include "core/render/bgr_picture.hpp"
#include "core/segmentation/csmp_segmentation.hpp"

namespace cosmos {

struct PatchPixelCentroid {
  int patch = 0;
  double column = 0;  // mean column and row of the patch's pixels
  double row = 0;
  int pixels = 0;
  // Where the id is drawn: the centroid when it lies inside the patch, clear of its boundary;
  // otherwise (a ring, a crescent) the patch's most interior pixel, which always lies inside.
  double label_column = 0;
  double label_row = 0;
};

// One entry per patch id that labels at least one pixel, ascending id, with label anchors.
std::vector<PatchPixelCentroid> patch_pixel_centroids(
    const PixelGrid<std::int32_t>& patch_of_pixel);

BgrPicture render_csmp_picture(const CsmpSegmentation& segmentation, double pixel_size_x_mm,
                               double pixel_size_y_mm);

}  // namespace cosmos
