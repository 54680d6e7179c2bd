#pragma once
// A model view's registration surface (ch. 6) for the recognizer: the view's own points when
// it has them (a base built in memory), else unpacked from the compact form that a base read
// from a file keeps (packed_registration_points.hpp), for as long as this object lives.
#include <cstdint>
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/parameter_visitor.hpp"
#include "core/registration/packed_registration_points.hpp"

namespace cosmos {

class ModelSurface {
 public:
  explicit ModelSurface(const ModelBaseView& view) : view_(view) {
    if (view.registration.size() == 0)
      unpacked_ = unpack_registration_points(view.registration_packed);
  }
  const RegistrationPoints& points() const {
    return view_.registration.size() > 0 ? view_.registration : unpacked_;
  }

 private:
  const ModelBaseView& view_;
  RegistrationPoints unpacked_;
};

// The surfaces one recognition needs, each unpacked once while it stays among the
// `capacity` most recently asked: verification, the pose search and the support measurement
// (which asks up to 20 views around each candidate, twice) come back to the same views again
// and again, and unpacking was a tenth of the recognizer's time. The bound keeps a
// recognition's memory fixed: the pose search alone asks for hundreds of views of the
// catalog's parts, and keeping every one unpacked until the recognition ended made the
// process's peak memory follow the hardest scan. A view asked again after being dropped is
// unpacked again, to the same points.
struct ModelSurfaceCacheParameters {
  // An unpacked view takes 104 bytes per control point besides its grid: 0.1-0.6 MB for the
  // default catalog's views (1,000-5,000 points), so the default bounds a recognition's
  // surfaces near 30 MB.
  int unpacked_views = 48;

  template <class Visitor>
  void visit(Visitor& v) {
    v("unpacked_views", unpacked_views,
      "model views a recognition keeps unpacked; up to ~0.6 MB each (104 bytes per point)",
      Range{1, 100000});
  }
};

class ModelSurfaces {
 public:
  ModelSurfaces(const ModelBase& base, const ModelSurfaceCacheParameters& parameters);

  // The view's points; the reference stays valid until the next call.
  const RegistrationPoints& points(int view);
  // The points of each of `views`, asked in that order (repeats allowed): with at most
  // capacity() different views among them, every one stays unpacked until the next call, so
  // the pointers may be read together (by several threads at once).
  std::vector<const RegistrationPoints*> points_of(const std::vector<int>& views);

  int capacity() const { return static_cast<int>(slots_.size()); }
  // Views unpacked so far, a view unpacked again counted again.
  std::int64_t unpackings() const { return unpackings_; }

 private:
  struct Slot {
    int view = -1;
    std::int64_t last_use = -1;
    RegistrationPoints points;
  };
  const ModelBase& base_;
  std::vector<int> slot_of_view_;
  std::vector<Slot> slots_;
  std::int64_t uses_ = 0;
  std::int64_t unpackings_ = 0;
};

}  // namespace cosmos
