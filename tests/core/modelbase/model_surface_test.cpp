// ModelSurfaces: a recognition's cache of unpacked model-view surfaces gives each view's
// points as unpacked from the file's compact form, once: the same object on every later ask.
#include "core/modelbase/model_surface.hpp"

#include <gtest/gtest.h>

#include "core/io/model_base_file.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

TEST(ModelSurfaces, UnpacksEachViewOnceAndAsTheViewItself) {
  const ModelBase base = read_model_base(testing::regression_model_base());
  ASSERT_GT(base.views.size(), 10u);
  ModelSurfaces surfaces(base);
  for (const int view : {0, 7, static_cast<int>(base.views.size()) - 1}) {
    const RegistrationPoints& cached = surfaces.points(view);
    const ModelSurface direct(base.views[static_cast<std::size_t>(view)]);
    ASSERT_GT(cached.size(), 0) << view;
    ASSERT_EQ(cached.size(), direct.points().size()) << view;
    EXPECT_EQ(cached.position_mm, direct.points().position_mm) << view;
    EXPECT_EQ(&surfaces.points(view), &cached) << view;
  }
  // Asking for other views later does not move the ones already unpacked.
  const RegistrationPoints* first = &surfaces.points(0);
  for (int view = 1; view < 10; ++view) surfaces.points(view);
  EXPECT_EQ(&surfaces.points(0), first);
}

}  // namespace
}  // namespace cosmos
