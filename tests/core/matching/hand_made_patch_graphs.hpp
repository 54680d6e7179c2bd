#pragma once
// Hand-made COSMOS views for the patch-group tests (§5.3): patches with only what the
// patch-group graph reads (id, area, shape index, curvedness, planarity, pixel count and the
// connectivity list V of Eq. 3.10), and the chain 0-1-2-3 of a cap, a ridge, a saddle and a
// cup of 300, 500, 200 and 400 mm^2 (1400 mm^2 in all), every contact 30 boundary pixels.
#include <utility>
#include <vector>

#include "core/representation/cosmos_view.hpp"

namespace cosmos::testing {

inline Csmp graph_patch(int id, double area_mm2, double shape_index,
                        std::vector<PatchNeighbor> neighbors, bool planar = false,
                        int pixels = 400) {
  Csmp patch;
  patch.id = id;
  patch.area_mm2 = area_mm2;
  patch.shape_index = planar ? 2.0 : shape_index;
  patch.mean_curvedness_per_mm = planar ? 0.0 : 0.05;
  patch.planar = planar;
  patch.pixels = pixels;
  patch.neighbors = std::move(neighbors);
  return patch;
}

inline CosmosView chain_view() {
  CosmosView view;
  view.patches = {
      graph_patch(0, 300, 0.95, {{1, 30}}), graph_patch(1, 500, 0.75, {{0, 30}, {2, 30}}),
      graph_patch(2, 200, 0.50, {{1, 30}, {3, 30}}), graph_patch(3, 400, 0.05, {{2, 30}})};
  return view;
}

}  // namespace cosmos::testing
