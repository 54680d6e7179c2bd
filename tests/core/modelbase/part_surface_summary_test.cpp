// A part's surface summary: its views' control points gathered in the part frame, into voxels
// and an even sample, each view's centroid in its own frame; views of other parts and views
// without points left out, and packed views summarized as their unpacked points.
#include "core/modelbase/part_surface_summary.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/registration/packed_registration_points.hpp"
#include "tests/core/registration/plane_range_image.hpp"

namespace cosmos {
namespace {

ModelBaseView plane_view(int part, double tilt_deg, const RigidTransform& T_scanner_part) {
  ModelBaseView view;
  view.part_index = part;
  view.T_scanner_part = T_scanner_part;
  RegistrationPointParameters parameters;
  parameters.stride_px = 2;
  view.registration =
      build_registration_points(testing::tilted_plane(tilt_deg, 60, 0.5), parameters).points;
  return view;
}

// Part 0: two planes seen from two poses and a view that measured nothing; part 1: one plane.
ModelBase two_part_base() {
  ModelBase base;
  base.parts.resize(2);
  RigidTransform turned;
  turned.rotation = rotation_from_xyz_angles_deg(20, 35, -10);
  turned.translation_mm = {3, -4, 40};
  base.views.push_back(plane_view(0, 10, RigidTransform::identity()));
  base.views.push_back(plane_view(1, -25, RigidTransform::identity()));
  base.views.push_back(plane_view(0, 30, turned));
  base.views.emplace_back().part_index = 0;
  return base;
}

std::vector<Eigen::Vector3d> points_in_part_frame(const ModelBase& base, int part) {
  std::vector<Eigen::Vector3d> points;
  for (const ModelBaseView& view : base.views) {
    if (view.part_index != part) continue;
    const RigidTransform T_part_view = view.T_scanner_part.inverse();
    for (Eigen::Index i = 0; i < view.registration.position_mm.cols(); ++i)
      points.push_back(T_part_view.apply(view.registration.position_mm.col(i)));
  }
  return points;
}

TEST(PartSurfaceSummary, GathersEachPartsOwnViewsInItsFrame) {
  ModelBase base = two_part_base();
  const PartDistanceFieldParameters parameters;
  summarize_part_surfaces(base, parameters);
  for (int part = 0; part < 2; ++part) {
    const std::vector<Eigen::Vector3d> points = points_in_part_frame(base, part);
    ASSERT_GT(points.size(), 300u);
    const PartSurfaceVoxels expected = part_surface_voxels(points, parameters);
    const ModelPart& summarized = base.parts[static_cast<std::size_t>(part)];
    EXPECT_EQ(summarized.surface_voxels.occupied_voxels, expected.occupied_voxels);
    EXPECT_EQ(summarized.surface_voxels.occupied_runs, expected.occupied_runs);
    EXPECT_EQ(summarized.surface_voxels.origin_mm, expected.origin_mm);
    // An even sample of about kSurfaceSamplePoints, every k-th point from the first.
    const std::size_t step = points.size() / kSurfaceSamplePoints;
    ASSERT_EQ(summarized.surface_sample_mm.size(), points.size() / step);
    EXPECT_EQ(summarized.surface_sample_mm[0], points[0]);
    EXPECT_EQ(summarized.surface_sample_mm[7], points[7 * step]);
  }
  EXPECT_NE(base.parts[0].surface_voxels.occupied_runs, base.parts[1].surface_voxels.occupied_runs);
  for (std::size_t v = 0; v < 3; ++v)
    EXPECT_TRUE(base.views[v].control_point_centroid_mm.isApprox(
        base.views[v].registration.position_mm.rowwise().mean(), 1e-12));
  EXPECT_NE(base.views[0].control_point_centroid_mm, Eigen::Vector3d::Zero());
  EXPECT_EQ(base.views[3].control_point_centroid_mm, Eigen::Vector3d::Zero());
}

TEST(PartSurfaceSummary, PackedViewsAreSummarizedAsTheirUnpackedPoints) {
  ModelBase unpacked = two_part_base();
  for (ModelBaseView& view : unpacked.views) {
    view.registration_packed = pack_registration_points(view.registration);
    view.registration = unpack_registration_points(view.registration_packed);
  }
  ModelBase packed = unpacked;
  for (ModelBaseView& view : packed.views) view.registration = RegistrationPoints{};
  summarize_part_surfaces(unpacked, {});
  summarize_part_surfaces(packed, {});
  for (std::size_t p = 0; p < 2; ++p) {
    EXPECT_EQ(packed.parts[p].surface_voxels.occupied_runs,
              unpacked.parts[p].surface_voxels.occupied_runs);
    EXPECT_EQ(packed.parts[p].surface_sample_mm, unpacked.parts[p].surface_sample_mm);
  }
  for (std::size_t v = 0; v < packed.views.size(); ++v)
    EXPECT_EQ(packed.views[v].control_point_centroid_mm,
              unpacked.views[v].control_point_centroid_mm);
}

}  // namespace
}  // namespace cosmos
