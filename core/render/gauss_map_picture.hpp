#pragma once
// gauss_map.png: the Gauss patch map (§3.2.2, Fig. 3.12) — the unit sphere seen from +z (the
// viewing direction) as an orthographic disc with a latitude/longitude graticule; each CSMP a
// filled disc at its orientation G0 (Eq. 3.7), area proportional to the patch area, coloured
// like csmps.png and labelled with its id; adjacency (Eq. 3.10) as thin lines. +x points right
// and +y down, as in the field pictures, so a patch appears on the side of the sphere it faces.
#include <Eigen/Core>

#include "core/render/bgr_picture.hpp"
#include "core/representation/cosmos_view.hpp"

namespace cosmos {

inline constexpr int kGaussMapSizePx = 640;    // square picture
inline constexpr int kGaussMapRadiusPx = 250;  // of the unit sphere, centred in the picture

// Picture position of a unit normal's orthographic projection (its x and y components).
Eigen::Vector2d gauss_map_position_px(const Eigen::Vector3d& normal);

BgrPicture render_gauss_map_picture(const CosmosView& view);

}  // namespace cosmos
