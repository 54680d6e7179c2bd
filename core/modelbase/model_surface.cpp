#include "core/modelbase/model_surface.hpp"

#include <algorithm>

namespace cosmos {

ModelSurfaces::ModelSurfaces(const ModelBase& base, const ModelSurfaceCacheParameters& parameters)
    : base_(base),
      slot_of_view_(base.views.size(), -1),
      slots_(static_cast<std::size_t>(std::max(parameters.unpacked_views, 1))) {}

const RegistrationPoints& ModelSurfaces::points(int view) {
  const ModelBaseView& model_view = base_.views[static_cast<std::size_t>(view)];
  if (model_view.registration.size() > 0) return model_view.registration;
  int& slot_index = slot_of_view_[static_cast<std::size_t>(view)];
  if (slot_index < 0) {
    // The least recently used slot (an empty one first: it was never used).
    const auto least_recent =
        std::min_element(slots_.begin(), slots_.end(),
                         [](const Slot& a, const Slot& b) { return a.last_use < b.last_use; });
    if (least_recent->view >= 0) slot_of_view_[static_cast<std::size_t>(least_recent->view)] = -1;
    least_recent->view = view;
    least_recent->points = RegistrationPoints{};  // freed before the next one is unpacked
    least_recent->points = unpack_registration_points(model_view.registration_packed);
    ++unpackings_;
    slot_index = static_cast<int>(least_recent - slots_.begin());
  }
  Slot& slot = slots_[static_cast<std::size_t>(slot_index)];
  slot.last_use = uses_++;
  return slot.points;
}

std::vector<const RegistrationPoints*> ModelSurfaces::points_of(const std::vector<int>& views) {
  // Each call evicts only the least recently asked view, never one of the last capacity()
  // different views asked, and a slot's points stay where they are until it is evicted.
  std::vector<const RegistrationPoints*> out;
  out.reserve(views.size());
  for (const int view : views) out.push_back(&points(view));
  return out;
}

}  // namespace cosmos
