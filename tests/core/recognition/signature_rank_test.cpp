// The parts the search over every part quick-fits first (signature_rank.hpp): ranked by their
// closest view's signature, and those within the ratio of the closest, at least min_parts.
#include "core/recognition/signature_rank.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cosmos {
namespace {

// A flat patch 40 mm square at `height_mm` above the belt, sampled every 2 mm.
ViewSignature flat_at(double height_mm) {
  Eigen::Matrix3Xd points(3, 20 * 20);
  for (int k = 0; k < 400; ++k)
    points.col(k) = Eigen::Vector3d(2.0 * (k % 20), 2.0 * (k / 20), height_mm);
  return view_signature(points, 0.0);
}

// Part p's views stand at the heights listed for it; a part without views has none.
struct Catalog {
  ModelBase base;
  std::vector<PartSearchModel> models;

  explicit Catalog(const std::vector<std::vector<double>>& view_heights_mm) {
    base.parts.resize(view_heights_mm.size());
    models.resize(view_heights_mm.size());
    for (std::size_t part = 0; part < view_heights_mm.size(); ++part)
      for (const double height_mm : view_heights_mm[part]) {
        ModelBaseView view;
        view.part_index = static_cast<int>(part);
        view.signature = flat_at(height_mm);
        models[part].views.push_back(static_cast<int>(base.views.size()));
        base.views.push_back(view);
      }
  }
};

TEST(SignatureRank, PartsRankByTheirClosestViewClosestFirst) {
  // The scene is a patch 50 mm up: part 1's second view is at it, part 0 has one 12 mm off,
  // part 3 one 28 mm off, part 2 none (every height mid-bin, so the distances are exact).
  const Catalog catalog({{10, 62}, {90, 50}, {}, {82, 22}});
  const std::vector<int> parts = {0, 1, 2, 3};
  const std::vector<PartSignatureDistance> ranked =
      rank_by_signature(flat_at(50), parts, catalog.base, catalog.models);
  ASSERT_EQ(ranked.size(), 4u);
  EXPECT_EQ(ranked[0].part, 1);
  EXPECT_NEAR(ranked[0].distance_mm, 0, 1e-9);
  EXPECT_EQ(ranked[1].part, 0);
  EXPECT_NEAR(ranked[1].distance_mm, 12, 1e-3);
  EXPECT_EQ(ranked[2].part, 3);
  EXPECT_NEAR(ranked[2].distance_mm, 28, 1e-3);
  EXPECT_EQ(ranked[3].part, 2);
  EXPECT_TRUE(std::isinf(ranked[3].distance_mm));
  // Only the parts asked for are ranked.
  const std::vector<int> some = {3, 2};
  EXPECT_EQ(rank_by_signature(flat_at(50), some, catalog.base, catalog.models).front().part, 3);
}

TEST(SignatureRank, ThePartsWithinTheRatioOfTheClosestAreFittedFirstAtLeastMinParts) {
  const std::vector<PartSignatureDistance> ranked = {
      {4, 2.0}, {0, 4.5}, {2, 5.0}, {1, 5.5}, {3, 30.0}};
  SignatureRankParameters parameters;
  parameters.ratio = 2.5;
  parameters.min_parts = 1;
  EXPECT_EQ(parts_fitted_first(ranked, parameters), 3u);  // within 5 mm
  parameters.min_parts = 4;
  EXPECT_EQ(parts_fitted_first(ranked, parameters), 4u);
  parameters.min_parts = 8;
  EXPECT_EQ(parts_fitted_first(ranked, parameters), 5u);  // all there are
  parameters.min_parts = 1;
  parameters.ratio = 1;
  EXPECT_EQ(parts_fitted_first(ranked, parameters), 1u);
  EXPECT_EQ(parts_fitted_first({}, parameters), 0u);
}

}  // namespace
}  // namespace cosmos
