#include "sim/orthographic_renderer.hpp"

#include <limits>

#include "sim/embree_scene.hpp"

namespace cosmos {

void render_orthographic(const ConveyorScene& scene, RangeImage& image) {
  constexpr int kPacket = 8;
  const Eigen::AlignedBox3d bounds = scene.bounds_mm();
  for (float& z : image.z_mm.values()) z = std::numeric_limits<float>::quiet_NaN();
  if (bounds.isEmpty()) return;
  const double top_z_mm = bounds.max().z() + 1.0;
  for (int row = 0; row < image.height(); ++row) {
    float* z_row = image.z_mm.row(row);
    for (int base = 0; base < image.width(); base += kPacket) {
      alignas(32) int valid[kPacket];
      RTCRayHit8 packet;
      for (int k = 0; k < kPacket; ++k) {
        valid[k] = base + k < image.width() ? -1 : 0;
        packet.ray.org_x[k] = static_cast<float>(image.x_mm(base + k));
        packet.ray.org_y[k] = 0.0f;  // relative to the row's y
        packet.ray.org_z[k] = static_cast<float>(top_z_mm);
        packet.ray.dir_x[k] = 0.0f;
        packet.ray.dir_y[k] = 0.0f;
        packet.ray.dir_z[k] = -1.0f;
        packet.ray.tnear[k] = 0.0f;
        packet.ray.tfar[k] = std::numeric_limits<float>::infinity();
        packet.ray.time[k] = 0.0f;
        packet.ray.mask[k] = 0xFFFFFFFFu;
        packet.ray.id[k] = static_cast<unsigned>(k);
        packet.ray.flags[k] = 0;
      }
      scene.embree().intersect8(valid, packet, image.y_mm(row));
      for (int k = 0; k < kPacket && base + k < image.width(); ++k) {
        if (packet.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) continue;
        z_row[base + k] = static_cast<float>(top_z_mm - static_cast<double>(packet.ray.tfar[k]));
      }
    }
  }
}

}  // namespace cosmos
