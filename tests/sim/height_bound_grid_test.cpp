// The coarse height bounds' belt-sight marking: every belt point whose line of sight the exact
// cell walk (clears) cannot clear is marked, and the marking leaves most of the line unmarked.
#include "sim/height_bound_grid.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "sim/procedural_meshes.hpp"

namespace cosmos {
namespace {

constexpr int kSamples = 640;
constexpr double kX0Mm = -127.8;
constexpr double kDxMm = 0.4;

struct MarkCounts {
  int blocked_unmarked = 0;  // must stay 0
  int blocked = 0;
  int marked = 0;
};

MarkCounts check_line(const HeightBoundGrid& grid, double y_mm, const Eigen::Vector3d& camera_mm) {
  const HeightBoundGrid::BeltSight sight = grid.belt_sight(y_mm, camera_mm);
  std::vector<int> difference(kSamples + 1, 0);
  grid.mark_belt_sights(sight, kX0Mm, kDxMm, kSamples, difference.data());
  MarkCounts counts;
  int running = 0;
  for (int i = 0; i < kSamples; ++i) {
    running += difference[static_cast<std::size_t>(i)];
    const Eigen::Vector3d belt_point(kX0Mm + i * kDxMm, y_mm, 0.0);
    const bool blocked =
        grid.may_block(sight, belt_point.x()) && !grid.clears(belt_point, camera_mm);
    counts.blocked += blocked;
    counts.marked += running > 0;
    counts.blocked_unmarked += blocked && running == 0;
  }
  return counts;
}

TEST(HeightBoundGrid, BeltSightMarksCoverEveryLineOfSightTheWalkCannotClear) {
  // A tall box turned about z and a sphere off-centre: cells of many heights, columns and rows.
  const TriangleMesh box = make_box(40.0, 25.0, 60.0);
  Eigen::Isometry3d T_belt_box = Eigen::Isometry3d::Identity();
  T_belt_box.rotate(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()));
  T_belt_box.pretranslate(Eigen::Vector3d(10.0, 0.0, 30.0));
  const TriangleMesh sphere = make_icosphere(20.0, 3);
  Eigen::Isometry3d T_belt_sphere = Eigen::Isometry3d::Identity();
  T_belt_sphere.pretranslate(Eigen::Vector3d(-60.0, 5.0, 20.0));
  for (const auto& [mesh, T_belt_part] :
       {std::pair{box, T_belt_box}, std::pair{sphere, T_belt_sphere}}) {
    const HeightBoundGrid grid(mesh, T_belt_part, 2.0);
    int blocked = 0;
    int marked = 0;
    // Cameras upstream and downstream, left, right and over the centre, at several heights.
    for (const Eigen::Vector3d& offset :
         {Eigen::Vector3d(0.0, 150.0, 260.0), Eigen::Vector3d(-80.0, -120.0, 200.0),
          Eigen::Vector3d(90.0, 60.0, 400.0)}) {
      for (double y_mm = -60.0; y_mm <= 60.0; y_mm += 0.4) {
        const MarkCounts counts = check_line(grid, y_mm, offset + Eigen::Vector3d(0.0, y_mm, 0.0));
        EXPECT_EQ(counts.blocked_unmarked, 0)
            << "y " << y_mm << " camera offset " << offset.transpose();
        blocked += counts.blocked;
        marked += counts.marked;
      }
    }
    EXPECT_GT(blocked, 1000);  // the scenes do hide belt points
    // The marks stay near the hidden points: far fewer than the 640 samples of every line.
    EXPECT_LT(marked, 3 * blocked);
  }
}

}  // namespace
}  // namespace cosmos
