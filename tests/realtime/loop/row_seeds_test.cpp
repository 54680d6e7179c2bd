// The CSMP seed search's first pass run row by row in the part builder gives the seeds that
// find_shape_seeds gives on the part's view, bit for bit: on reliefs, planar facets, a
// reused builder, two parts side by side in the same rows and a part whose two legs the
// tracker merges; and it refuses a part a growing edge ties to an id the part does not own.
#include "realtime/loop/row_seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>

#include "core/segmentation/csmp_segmentation.hpp"
#include "realtime/loop/incremental_cosmos.hpp"

namespace cosmos {
namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

using Height = std::function<float(double x, double y)>;  // mm; NaN: no data
using IdOf = std::function<std::int64_t(int column, int row)>;

RangeImage sampled(int width, int height, const Height& z, std::uint64_t seed) {
  RangeImage image(width, height, 0.4, 0.4);
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const float h = z(column * 0.4, row * 0.4);
      image.z_mm(column, row) = std::isnan(h) ? kNan : static_cast<float>(h + noise(generator));
    }
  return image;
}

// Bumps, a dent, a 6 mm step and a hole of missing data.
float relief(double x, double y) {
  if ((x - 20) * (x - 20) + (y - 30) * (y - 30) < 9) return kNan;
  double z = 12 * std::exp(-((x - 12) * (x - 12) + (y - 14) * (y - 14)) / 60.0) -
             6 * std::exp(-((x - 30) * (x - 30) + (y - 22) * (y - 22)) / 40.0) + 0.2 * x;
  if (x > 38) z += 6.0;
  return static_cast<float>(z);
}

// A four-sided pyramid: planar facets meeting at creases.
float pyramid(double x, double y) {
  return static_cast<float>(20 - 0.6 * std::max(std::abs(x - 24), std::abs(y - 20)));
}

RowBlockPool& test_pool() {
  static RowBlockPool pool(64, 16 * PartRows::record_bytes(160));
  return pool;
}

// Feeds the image to the builder with the tracker ids `id_of` gives its sampled pixels.
void build(IncrementalCosmos& builder, const RangeImage& image, const IdOf& id_of) {
  builder.begin_part(0, 0);
  for (int row = 0; row < image.height(); ++row) {
    ASSERT_EQ(builder.add_row(image.z_mm.row(row)), AddRowResult::kAdded);
    const PartRow record = builder.row(row);
    for (int column = record.column_begin; column < record.column_end; ++column)
      record.tracker_label[record.at(column)] =
          std::isnan(image.z_mm(column, row)) ? -1 : id_of(column, row);
  }
  builder.finish();
}

// The builder's field with only the pixels of ids `owns` accepts, as the part's view keeps
// them: others unlabelled, and no link towards them.
ShapeIndexField owned_view(const IncrementalCosmos& builder,
                           const std::function<bool(std::int64_t)>& owns) {
  ShapeIndexField field = builder.whole_field();
  const int width = field.width(), height = field.height();
  PixelGrid<std::uint8_t> owned(width, height, 0);
  for (int row = 0; row < height; ++row) {
    const PartRow record = builder.row(row);
    for (int column = record.column_begin; column < record.column_end; ++column)
      owned(column, row) = owns(record.tracker_label[record.at(column)]) ? 1 : 0;
  }
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      if (!owned(column, row)) {
        field.label(column, row) = SurfaceLabel::kInvalid;
        field.same_side(column, row) = 0;
        continue;
      }
      for (int k = 0; k < 8; ++k) {
        const int c = column + kNeighborOffsets[k].column, r = row + kNeighborOffsets[k].row;
        if (c < 0 || r < 0 || c >= width || r >= height || !owned(c, r))
          field.same_side(column, row) &= static_cast<std::uint8_t>(~(1u << k));
      }
    }
  return field;
}

// The builder's seeds of the part owning `owns` equal find_shape_seeds on its view; returns
// the number of seeds.
int expect_seeds_of_view(const IncrementalCosmos& builder,
                         const std::function<bool(std::int64_t)>& owns) {
  EXPECT_TRUE(builder.seeds().holds_part(owns));
  const ShapeIndexField view = owned_view(builder, owns);
  const std::optional<ShapeSeeds> from_rows = builder.seeds().view_seeds(view, 0);
  EXPECT_TRUE(from_rows.has_value());
  if (!from_rows) return 0;
  const DarbouxFrameField frames = builder.whole_frames();
  const SegmentationParameters parameters;
  const ShapeSeeds whole = find_shape_seeds(frames, view, parameters);
  EXPECT_EQ(from_rows->seed_of_pixel, whole.seed_of_pixel);
  EXPECT_EQ(from_rows->shape_index_min, whole.shape_index_min);
  EXPECT_EQ(from_rows->shape_index_max, whole.shape_index_max);
  EXPECT_EQ(from_rows->area_mm2, whole.area_mm2);
  EXPECT_EQ(from_rows->shape_area, whole.shape_area);
  EXPECT_EQ(from_rows->adjacent, whole.adjacent);
  const CsmpSegmentation grown = segment_csmps_from_seeds(view, *from_rows, parameters);
  const CsmpSegmentation expected = segment_csmps(frames, view, parameters);
  EXPECT_EQ(grown.patch_count, expected.patch_count);
  EXPECT_EQ(grown.patch_of_pixel.values(), expected.patch_of_pixel.values());
  return whole.seed_count();
}

bool any_id(std::int64_t id) { return id >= 0; }

TEST(RowSeeds, EqualTheSeedsOfTheWholeImageOnReliefsAndFacets) {
  CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 120, 200, 0.4, 0.4, test_pool());
  int seeds = 0, adjacent_pairs = 0;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    build(builder, sampled(120, 110, relief, seed), [](int, int) { return 5; });
    seeds += expect_seeds_of_view(builder, any_id);
    adjacent_pairs += builder.seeds().view_seeds(builder.whole_field(), 0)->adjacent.size();
  }
  build(builder, sampled(120, 100, pyramid, 4), [](int, int) { return 5; });
  seeds += expect_seeds_of_view(builder, any_id);
  // Enough seeds and pairs that an order or a pair out of place would show.
  EXPECT_GT(seeds, 300);
  EXPECT_GT(adjacent_pairs, 300);
}

TEST(RowSeeds, AReusedBuilderEqualsAFreshOneAfterALongerWiderPart) {
  CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 150, 200, 0.4, 0.4, test_pool());
  build(builder, sampled(150, 180, relief, 7), [](int, int) { return 1; });
  const RangeImage second = sampled(
      150, 60, [](double x, double y) { return x < 12 || x > 40 ? kNan : relief(x, y); }, 8);
  build(builder, second, [](int, int) { return 2; });
  EXPECT_GT(expect_seeds_of_view(builder, any_id), 20);
}

TEST(RowSeeds, TwoPartsSideBySideInTheSameRowsEachGetTheirOwnViewsSeeds) {
  CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 140, 200, 0.4, 0.4, test_pool());
  // Two reliefs across the belt with 4 mm of empty belt between them.
  const auto two = [](double x, double y) -> float {
    if (x >= 26 && x < 30) return kNan;
    return x < 26 ? relief(x + 6, y) : relief(x - 24, y + 5);
  };
  build(builder, sampled(140, 100, two, 9),
        [](int column, int) { return column * 0.4 < 28 ? 3 : 4; });
  EXPECT_GT(expect_seeds_of_view(builder, [](std::int64_t id) { return id == 3; }), 20);
  EXPECT_GT(expect_seeds_of_view(builder, [](std::int64_t id) { return id == 4; }), 20);
}

TEST(RowSeeds, APartWhoseLegsTheTrackerMergedHasTheSeedsOfItsWholeView) {
  CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 120, 200, 0.4, 0.4, test_pool());
  // A U upside down: two legs 8 mm apart, which a bar joins from row 60 on. The tracker gave
  // the legs ids 1 and 2 and, once the bar merged them, id 1.
  const auto arch = [](double x, double y) -> float {
    const bool leg = (x >= 6 && x < 20) || (x >= 28 && x < 42);
    if (!leg && !(y >= 24 && x >= 6 && x < 42)) return kNan;
    return static_cast<float>(10 + 3 * std::sin(x / 5) + 2 * std::cos(y / 7));
  };
  const auto ids = [](int column, int row) -> std::int64_t {
    return row < 60 && column * 0.4 >= 24 ? 2 : 1;
  };
  build(builder, sampled(120, 100, arch, 10), ids);
  EXPECT_GT(expect_seeds_of_view(builder, [](std::int64_t id) { return id == 1 || id == 2; }), 5);
  // A part owning only one of the merged ids is not one the rows' seeds can give.
  EXPECT_FALSE(builder.seeds().holds_part([](std::int64_t id) { return id == 1; }));
  EXPECT_FALSE(builder.seeds().holds_part([](std::int64_t id) { return id == 2; }));
}

TEST(RowSeeds, AViewWithRowsNotYetSeededIsRefused) {
  CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 120, 200, 0.4, 0.4, test_pool());
  const RangeImage image = sampled(120, 60, relief, 11);
  builder.begin_part(0, 0);
  for (int row = 0; row < image.height(); ++row)
    ASSERT_EQ(builder.add_row(image.z_mm.row(row)), AddRowResult::kAdded);
  // Not finished: the last rows' shape index is not final, so neither are their seeds.
  EXPECT_LT(builder.seeds().seeded_rows(), image.height());
  EXPECT_FALSE(builder.seeds().view_seeds(make_shape_index_field(120, 60), 0).has_value());
  builder.finish();
  EXPECT_EQ(builder.seeds().seeded_rows(), image.height());
}

}  // namespace
}  // namespace cosmos
