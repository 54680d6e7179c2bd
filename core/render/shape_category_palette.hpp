#pragma once
// The nine shape categories of Fig. 3.3 and the colours every picture uses for them, plus the
// per-patch palette shared by csmps.png and gauss_map.png.
//
// Category colours run from blue (cup, concave) through green (saddle) to red (cap, convex),
// the usual convention for shape-index maps; planar is neutral grey, no data black.
#include <array>
#include <string_view>

#include "core/render/bgr_picture.hpp"

namespace cosmos {

inline constexpr int kShapeCategories = 9;

struct ShapeCategory {
  std::string_view name;
  std::string_view interval;  // on the S_I scale, as printed in Fig. 3.3
  double lower = 0;           // S_I in [lower, upper); the cap includes 1
  double upper = 0;
  BgrColor color;
};

// Fig. 3.3, ordered by S_I: the boundaries are the odd sixteenths.
inline constexpr std::array<ShapeCategory, kShapeCategories> kShapeCategoryTable{{
    {"cup", "[0, 1/16)", 0.0 / 16, 1.0 / 16, rgb(35, 60, 200)},
    {"trough", "[1/16, 3/16)", 1.0 / 16, 3.0 / 16, rgb(40, 140, 235)},
    {"rut", "[3/16, 5/16)", 3.0 / 16, 5.0 / 16, rgb(40, 205, 225)},
    {"saddle rut", "[5/16, 7/16)", 5.0 / 16, 7.0 / 16, rgb(55, 185, 125)},
    {"saddle", "[7/16, 9/16)", 7.0 / 16, 9.0 / 16, rgb(125, 205, 55)},
    {"saddle ridge", "[9/16, 11/16)", 9.0 / 16, 11.0 / 16, rgb(215, 220, 45)},
    {"ridge", "[11/16, 13/16)", 11.0 / 16, 13.0 / 16, rgb(250, 170, 40)},
    {"dome", "[13/16, 15/16)", 13.0 / 16, 15.0 / 16, rgb(240, 95, 40)},
    {"cap", "[15/16, 1]", 15.0 / 16, 16.0 / 16, rgb(185, 20, 35)},
}};

inline constexpr BgrColor kPlanarColor = rgb(150, 150, 150);
inline constexpr BgrColor kNoDataColor = rgb(0, 0, 0);
// csmps.png draws patch boundaries in this; it is darker than every patch colour.
inline constexpr BgrColor kBoundaryColor = rgb(40, 40, 40);

// Index into kShapeCategoryTable of a shape index in [0, 1] (values outside are clamped).
int shape_category_index(double shape_index);
BgrColor shape_category_color(double shape_index);

// A deterministic, well-spread colour per patch id (golden-ratio hue steps), never dark, so
// that the boundary colour and no-data black stay distinct from every patch.
BgrColor patch_color(int patch_id);

}  // namespace cosmos
