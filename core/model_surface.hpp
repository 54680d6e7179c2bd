#pragma once
// A model view's registration surface (ch. 6) for the recognizer: the view's own points when
// it has them (a base built in memory), else unpacked from the compact form that a base read
// from a file keeps (packed_registration_points.hpp), for as long as this object lives.
#include "core/model_base.hpp"
#include "core/packed_registration_points.hpp"

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

}  // namespace cosmos
