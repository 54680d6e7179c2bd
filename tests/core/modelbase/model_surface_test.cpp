// ModelSurfaces: a recognition's bounded cache of unpacked model-view surfaces gives each
// view's points as unpacked from the file's compact form, once while the view stays among
// the most recently asked, and again (the same points) after it was dropped.
#include "core/modelbase/model_surface.hpp"

#include <gtest/gtest.h>

#include "core/io/model_base_file.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

TEST(ModelSurfaces, UnpacksEachViewOnceAndAsTheViewItself) {
  const ModelBase base = read_model_base(testing::regression_model_base());
  ASSERT_GT(base.views.size(), 10u);
  ModelSurfaces surfaces(base, {.unpacked_views = 16});
  for (const int view : {0, 7, static_cast<int>(base.views.size()) - 1}) {
    const RegistrationPoints& cached = surfaces.points(view);
    const ModelSurface direct(base.views[static_cast<std::size_t>(view)]);
    ASSERT_GT(cached.size(), 0) << view;
    ASSERT_EQ(cached.size(), direct.points().size()) << view;
    EXPECT_EQ(cached.position_mm, direct.points().position_mm) << view;
    EXPECT_EQ(&surfaces.points(view), &cached) << view;
  }
  EXPECT_EQ(surfaces.unpackings(), 3);
  // Asking for other views within the capacity does not move the ones already unpacked.
  const RegistrationPoints* first = &surfaces.points(0);
  for (int view = 1; view < 10; ++view) surfaces.points(view);
  EXPECT_EQ(&surfaces.points(0), first);
  EXPECT_EQ(surfaces.unpackings(), 11);
}

TEST(ModelSurfaces, KeepsAtMostItsCapacityAndDropsTheLeastRecentlyAsked) {
  const ModelBase base = read_model_base(testing::regression_model_base());
  ASSERT_GT(base.views.size(), 10u);
  ModelSurfaces surfaces(base, {.unpacked_views = 3});
  EXPECT_EQ(surfaces.capacity(), 3);
  surfaces.points(0);
  surfaces.points(1);
  surfaces.points(2);
  surfaces.points(0);  // 1 is now the least recently asked
  EXPECT_EQ(surfaces.unpackings(), 3);
  surfaces.points(3);  // drops 1
  EXPECT_EQ(surfaces.unpackings(), 4);
  surfaces.points(0);
  surfaces.points(2);
  surfaces.points(3);
  EXPECT_EQ(surfaces.unpackings(), 4);
  // View 1 comes back unpacked again, equal to its direct unpacking.
  const RegistrationPoints& again = surfaces.points(1);
  EXPECT_EQ(surfaces.unpackings(), 5);
  const ModelSurface direct(base.views[1]);
  EXPECT_EQ(again.position_mm, direct.points().position_mm);
  EXPECT_EQ(again.surface, direct.points().surface);
  EXPECT_EQ(again.cell_point, direct.points().cell_point);
}

TEST(ModelSurfaces, AViewBuiltInMemoryIsItsOwnPointsAndTakesNoSlot) {
  ModelBase base = read_model_base(testing::regression_model_base());
  base.views[0].registration = ModelSurface(base.views[0]).points();
  ModelSurfaces surfaces(base, {.unpacked_views = 1});
  EXPECT_EQ(&surfaces.points(0), &base.views[0].registration);
  EXPECT_EQ(surfaces.unpackings(), 0);
}

}  // namespace
}  // namespace cosmos
