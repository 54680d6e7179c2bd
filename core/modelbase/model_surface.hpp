#pragma once
// A model view's registration surface (ch. 6) for the recognizer: the view's own points when
// it has them (a base built in memory), else unpacked from the compact form that a base read
// from a file keeps (packed_registration_points.hpp), for as long as this object lives.
#include <memory>
#include <vector>

#include "core/modelbase/model_base.hpp"
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

// The surfaces one recognition needs, each unpacked once: verification, the pose search and
// the support measurement (which asks up to 20 views around each candidate, twice) come back
// to the same views again and again, and unpacking was a tenth of the recognizer's time.
class ModelSurfaces {
 public:
  explicit ModelSurfaces(const ModelBase& base)
      : base_(base), slot_of_view_(base.views.size(), -1) {}
  const RegistrationPoints& points(int view) {
    int& slot = slot_of_view_[static_cast<std::size_t>(view)];
    if (slot < 0) {
      slot = static_cast<int>(surfaces_.size());
      surfaces_.push_back(
          std::make_unique<ModelSurface>(base_.views[static_cast<std::size_t>(view)]));
    }
    return surfaces_[static_cast<std::size_t>(slot)]->points();
  }

 private:
  const ModelBase& base_;
  std::vector<int> slot_of_view_;
  std::vector<std::unique_ptr<ModelSurface>> surfaces_;
};

}  // namespace cosmos
