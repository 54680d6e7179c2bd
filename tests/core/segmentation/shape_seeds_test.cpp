// Seeds of region growing (shape_seeds.hpp) on hand-made fields whose answer is known.
#include "core/segmentation/shape_seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <utility>

namespace cosmos {
namespace {

// A curved field with every in-image neighbour on the same side, unit areas, upward normals.
struct HandField {
  DarbouxFrameField frames;
  ShapeIndexField field;
};

HandField hand_field(int width, int height, float (*shape_index_at)(int column, int row)) {
  HandField out{DarbouxFrameField(width, height), make_shape_index_field(width, height)};
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const std::size_t i = out.field.label.index(column, row);
      out.field.label[i] = SurfaceLabel::kCurved;
      out.field.shape_index[i] = shape_index_at(column, row);
      out.field.area_mm2[i] = 1.0f;
      out.frames.frame[kNz][i] = 1.0f;
      std::uint8_t mask = 0;
      for (int k = 0; k < 8; ++k)
        if (out.field.label.contains(column + kNeighborOffsets[k].column,
                                     row + kNeighborOffsets[k].row))
          mask |= static_cast<std::uint8_t>(1u << k);
      out.field.same_side[i] = out.frames.same_side[i] = mask;
    }
  }
  return out;
}

std::set<std::pair<int, int>> unique_pairs(const ShapeSeeds& seeds) {
  std::set<std::pair<int, int>> pairs;
  for (const auto& [a, b] : seeds.adjacent) pairs.insert({std::min(a, b), std::max(a, b)});
  return pairs;
}

TEST(ShapeSeeds, SeedsStayWithinOneQuantumAndAccountForEveryPixel) {
  const HandField ramp = hand_field(40, 10, [](int column, int row) {
    return 0.1f + 0.004f * static_cast<float>(column) + 0.001f * static_cast<float>(row % 3);
  });
  const SegmentationParameters parameters;
  const ShapeSeeds seeds = find_shape_seeds(ramp.frames, ramp.field, parameters);
  ASSERT_GT(seeds.seed_count(), 4);  // the ramp spans 0.16 of S_I
  std::vector<float> low(seeds.seed_count(), 9), high(seeds.seed_count(), -9);
  std::vector<double> area(seeds.seed_count(), 0), shape_area(seeds.seed_count(), 0);
  for (std::size_t i = 0; i < ramp.field.label.size(); ++i) {
    const int seed = seeds.seed_of_pixel[i];
    ASSERT_GE(seed, 0);
    ASSERT_LT(seed, seeds.seed_count());
    low[seed] = std::min(low[seed], ramp.field.shape_index[i]);
    high[seed] = std::max(high[seed], ramp.field.shape_index[i]);
    area[seed] += 1.0;
    shape_area[seed] += ramp.field.shape_index[i];
  }
  for (int seed = 0; seed < seeds.seed_count(); ++seed) {
    EXPECT_FLOAT_EQ(seeds.shape_index_min[seed], low[seed]);
    EXPECT_FLOAT_EQ(seeds.shape_index_max[seed], high[seed]);
    EXPECT_LE(high[seed] - low[seed], parameters.seed_shape_index_quantum + 1e-6);
    EXPECT_FLOAT_EQ(seeds.area_mm2[seed], static_cast<float>(area[seed]));
    EXPECT_NEAR(seeds.shape_area[seed], shape_area[seed], 1e-5);
  }
  // Seed ids follow the raster order of their first pixel.
  int next = 0;
  for (std::size_t i = 0; i < ramp.field.label.size(); ++i)
    if (seeds.seed_of_pixel[i] == next) ++next;
  EXPECT_EQ(next, seeds.seed_count());

  // Every pair of different seeds that meet across an 8-adjacency is listed, and only those.
  std::set<std::pair<int, int>> meeting;
  int crossings = 0;  // pixel pairs across seed boundaries, each counted from both sides
  for (int row = 0; row < 10; ++row)
    for (int column = 0; column < 40; ++column)
      for (const PixelOffset& offset : kNeighborOffsets) {
        if (!ramp.field.label.contains(column + offset.column, row + offset.row)) continue;
        const int a = seeds.seed_of_pixel[ramp.field.label.index(column, row)];
        const int b =
            seeds.seed_of_pixel[ramp.field.label.index(column + offset.column, row + offset.row)];
        if (a == b) continue;
        meeting.insert({std::min(a, b), std::max(a, b)});
        ++crossings;
      }
  EXPECT_EQ(unique_pairs(seeds), meeting);
  // A pair recurs along its boundary, between rows and directions, yet is listed once: the
  // table of recently listed pairs holds every pair of so small an image.
  EXPECT_GT(crossings, 4 * static_cast<int>(meeting.size()));
  EXPECT_EQ(seeds.adjacent.size(), meeting.size());
}

TEST(ShapeSeeds, APixelJoinsTheNeighbourSeedOfLeastJoinedRangeFirst) {
  // Row 0: A = 0.50 and B = 0.53, too far apart for one seed. Below A, x = 0.52 could join
  // either (range 0.02 with A, 0.01 with B) but not both (0.03): it joins B.
  const HandField field = hand_field(2, 2, [](int column, int row) {
    if (row == 0) return column == 0 ? 0.50f : 0.53f;
    return column == 0 ? 0.52f : 0.90f;
  });
  const ShapeSeeds seeds = find_shape_seeds(field.frames, field.field, SegmentationParameters{});
  const auto seed = [&](int column, int row) {
    return seeds.seed_of_pixel[field.field.label.index(column, row)];
  };
  EXPECT_NE(seed(0, 0), seed(1, 0));
  EXPECT_EQ(seed(0, 1), seed(1, 0));
  EXPECT_EQ(seeds.seed_count(), 3);
  EXPECT_TRUE(unique_pairs(seeds).count(
      {std::min(seed(0, 0), seed(1, 0)), std::max(seed(0, 0), seed(1, 0))}));
}

TEST(ShapeSeeds, CreasesDepthJumpsAndLabelsSeparateSeeds) {
  // Columns 0-3 planar facing up, 4-7 planar tilted 30 degrees (a crease between them); row 2
  // curved at one shape index but cut from row 1 by a depth jump.
  HandField field = hand_field(8, 3, [](int, int) { return 0.3f; });
  for (int column = 0; column < 8; ++column) {
    for (int row = 0; row < 2; ++row) {
      const std::size_t i = field.field.label.index(column, row);
      field.field.label[i] = SurfaceLabel::kPlanar;
      field.field.shape_index[i] = kPlanarShapeIndex;
      if (column >= 4) {
        field.frames.frame[kNx][i] = 0.5f;
        field.frames.frame[kNz][i] = 0.8660254f;
      }
    }
  }
  for (int column = 0; column < 8; ++column) {
    // Rows 1 and 2 on different sides of a depth jump: no same-side bits across.
    const std::size_t above = field.field.label.index(column, 1);
    const std::size_t below = field.field.label.index(column, 2);
    field.field.same_side[above] &= static_cast<std::uint8_t>(~0xE0u);  // below-left/below/-right
    field.field.same_side[below] &= static_cast<std::uint8_t>(~0x07u);  // up-left/up/up-right
  }
  const ShapeSeeds seeds = find_shape_seeds(field.frames, field.field, SegmentationParameters{});
  ASSERT_EQ(seeds.seed_count(), 3);
  const auto seed = [&](int column, int row) {
    return seeds.seed_of_pixel[field.field.label.index(column, row)];
  };
  for (int column = 0; column < 8; ++column) {
    EXPECT_EQ(seed(column, 0), seed(column, 1));
    EXPECT_EQ(seed(column, 0), column < 4 ? seed(0, 0) : seed(7, 0));
    EXPECT_EQ(seed(column, 2), seed(0, 2));
  }
  EXPECT_FLOAT_EQ(seeds.shape_index_min[seed(0, 0)], kPlanarShapeIndex);
  EXPECT_FLOAT_EQ(seeds.area_mm2[seed(0, 2)], 8.0f);
  EXPECT_TRUE(seeds.adjacent.empty());  // no growing edge crosses a crease, jump or label
}

TEST(ShapeSeeds, PairsComeInRasterOrderOfTheirLastCrossingEdge) {
  // Shape indices scattered over 0.1 of S_I: seeds of a few pixels, and pixels whose
  // neighbours lie in two or three seeds they do not join.
  const HandField noisy = hand_field(16, 12, [](int column, int row) {
    const auto hash = static_cast<std::uint32_t>(column * 73856093 ^ row * 19349663) * 2654435761u;
    return 0.4f + 0.1f * static_cast<float>(hash >> 8) / static_cast<float>(1u << 24);
  });
  const ShapeSeeds seeds = find_shape_seeds(noisy.frames, noisy.field, SegmentationParameters{});
  ASSERT_GT(seeds.seed_count(), 30);
  // Every backward edge (all are growing edges here) between different seeds, in raster order
  // of its later pixel, then by direction: a pair's place is that of its last such edge, and
  // it is listed as (earlier pixel's seed, later pixel's seed) of that edge.
  std::map<std::pair<int, int>, std::pair<int, std::pair<int, int>>> last_edge;
  int crossing_pixels = 0;  // pixels with edges into two or more other seeds
  for (int row = 0; row < 12; ++row) {
    for (int column = 0; column < 16; ++column) {
      const int a = seeds.seed_of_pixel[noisy.field.label.index(column, row)];
      std::set<int> others;
      for (int k = 0; k < 4; ++k) {
        const PixelOffset offset = kNeighborOffsets[k];
        if (!noisy.field.label.contains(column + offset.column, row + offset.row)) continue;
        const int b =
            seeds.seed_of_pixel[noisy.field.label.index(column + offset.column, row + offset.row)];
        if (a == b) continue;
        others.insert(b);
        const int place = (row * 16 + column) * 4 + k;
        last_edge[{std::min(a, b), std::max(a, b)}] = {place, {b, a}};
      }
      crossing_pixels += others.size() >= 2;
    }
  }
  ASSERT_GT(crossing_pixels, 10);
  std::vector<std::pair<int, std::pair<int, int>>> by_place;
  for (const auto& [pair, edge] : last_edge) by_place.push_back(edge);
  std::sort(by_place.begin(), by_place.end());
  std::vector<std::pair<std::int32_t, std::int32_t>> expected;
  for (const auto& [place, pair] : by_place) expected.emplace_back(pair.first, pair.second);
  // A pair the table of recent pairs lost is listed again at an earlier edge: its last copy
  // keeps its place.
  std::vector<std::pair<std::int32_t, std::int32_t>> last_copies;
  std::set<std::pair<int, int>> seen;
  for (auto pair = seeds.adjacent.rbegin(); pair != seeds.adjacent.rend(); ++pair)
    if (seen.insert({std::min(pair->first, pair->second), std::max(pair->first, pair->second)})
            .second)
      last_copies.push_back(*pair);
  std::reverse(last_copies.begin(), last_copies.end());
  EXPECT_EQ(last_copies, expected);
}

}  // namespace
}  // namespace cosmos
