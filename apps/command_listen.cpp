// `cosmos listen [--url URL] [--channel C]... [--count N] [--timeout-s S]`: subscribes to the
// cell's LCM channels and prints every message decoded, one line each, so a user (or a test)
// sees what the robot receives. Bounded by a message count and/or a timeout.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/command_registry.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_connection.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"

namespace cosmos::cli {
namespace {

struct ListenOptions {
  std::string url = kDefaultLcmUrl;
  std::vector<std::string> channels;  // empty: all three
  int count = 0;                      // 0: no limit
  double timeout_s = 0.0;             // 0: no limit
};

std::string format_pose(const PartPose& pose) {
  const Eigen::Vector3d& t_mm = pose.translation_cell_part_mm;
  const Eigen::Quaterniond& q = pose.rotation_cell_part;
  std::ostringstream line;
  line << kPoseChannel << " seq=" << pose.part_seq
       << " part=" << (pose.part_name.empty() ? "-" : pose.part_name)
       << " index=" << pose.part_index << " view=" << pose.view_index
       << " status=" << to_string(pose.status) << " encoder=" << pose.encoder_ticks << " pos_m=["
       << t_mm.x() / kMillimetresPerMetre << ' ' << t_mm.y() / kMillimetresPerMetre << ' '
       << t_mm.z() / kMillimetresPerMetre << "] q_wxyz=[" << q.w() << ' ' << q.x() << ' ' << q.y()
       << ' ' << q.z() << "] score=" << pose.score << " rms_mm=" << pose.registration_rms_mm
       << " latency_ms=" << pose.latency_ms;
  if (!pose.reason.empty()) line << " reason=\"" << pose.reason << '"';
  return line.str();
}

std::string format_status(const CellStatus& status) {
  std::ostringstream line;
  line << kStatusChannel << " state=" << to_string(status.state) << " text=\"" << status.state_text
       << '"';
  CellStatus::visit_totals(status, [&line](const char* name, std::int64_t total, const char*) {
    line << ' ' << name << '=' << total;
  });
  line << " p50_us=" << status.profile_time_p50_us << " p99_us=" << status.profile_time_p99_us
       << " max_us=" << status.profile_time_max_us
       << " recognition_queue=" << status.recognition_queue_depth
       << " publish_queue=" << status.publish_queue_depth;
  return line.str();
}

std::string format_profile(const Profile& profile) {
  std::size_t valid = 0;
  float min_z_mm = 0.0F;
  float max_z_mm = 0.0F;
  for (const float z_mm : profile.z_mm) {
    if (std::isnan(z_mm)) continue;
    min_z_mm = valid == 0 ? z_mm : std::min(min_z_mm, z_mm);
    max_z_mm = valid == 0 ? z_mm : std::max(max_z_mm, z_mm);
    ++valid;
  }
  std::ostringstream line;
  line << kProfileChannel << " seq=" << profile.seq << " encoder=" << profile.encoder_ticks
       << " t_us=" << profile.t_us << " x0_mm=" << profile.x0_mm << " dx_mm=" << profile.dx_mm
       << " width=" << profile.width() << " valid=" << valid << " z_mm=[";
  if (valid > 0) line << min_z_mm << ' ' << max_z_mm;
  line << ']';
  return line.str();
}

// Decodes by channel name rather than through LCM's typed subscriptions, so a message of
// the wrong type prints as one line here instead of LCM's complaint on stderr.
class Listener {
 public:
  std::string describe(const std::string& channel, const void* data, std::size_t size) {
    if (channel == kPoseChannel && decode_message(data, size, pose_message_)) {
      from_message(pose_message_, pose_);
      return format_pose(pose_);
    }
    if (channel == kStatusChannel && decode_message(data, size, status_message_)) {
      from_message(status_message_, status_);
      return format_status(status_);
    }
    if (channel == kProfileChannel) {
      // No config here: bounded by the widest profile any scanner config gives.
      if (decode_message(data, size, kMaxProfileWidth, profile_message_) &&
          from_message(profile_message_, profile_)) {
        return format_profile(profile_);
      }
    }
    return channel + " undecodable message of " + std::to_string(size) + " bytes";
  }

  void on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    std::cout << describe(channel, buffer->data, buffer->data_size) << std::endl;
    ++received;
  }

  int received = 0;

 private:
  cosmos_lcm::part_pose_t pose_message_{};
  cosmos_lcm::cell_status_t status_message_{};
  cosmos_lcm::range_profile_t profile_message_{};
  PartPose pose_;
  CellStatus status_;
  Profile profile_;
};

void run_listen(const ListenOptions& options) {
  std::vector<std::string> channels = options.channels;
  if (channels.empty()) channels = {kPoseChannel, kStatusChannel, kProfileChannel};

  const std::unique_ptr<lcm::LCM> lcm = open_lcm(options.url);
  Listener listener;
  std::string channel_list;
  for (const std::string& channel : channels) {
    lcm->subscribe(channel, &Listener::on_message, &listener);
    channel_list += channel + " ";
  }
  // Subscribed from here on: a script may start its publisher once it sees this line.
  std::cerr << "listen: " << channel_list << "on " << options.url << std::endl;

  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  while (options.count == 0 || listener.received < options.count) {
    int wait_ms = 1000;
    if (options.timeout_s > 0.0) {
      // In seconds as a double: no overflow for huge timeouts, rounded up so that the last
      // wait is never 0 ms (a busy loop).
      const double left_s =
          options.timeout_s - std::chrono::duration<double>(Clock::now() - start).count();
      if (left_s <= 0.0) break;
      wait_ms = static_cast<int>(std::min(1000.0, std::ceil(left_s * 1000.0)));
    }
    if (lcm->handleTimeout(wait_ms) < 0)
      throw std::runtime_error("listen: receiving from " + options.url + " failed");
  }
  if (options.count > 0 && listener.received < options.count) {
    std::ostringstream reason;
    reason << "listen: " << listener.received << " of " << options.count << " messages within "
           << options.timeout_s << " s on " << options.url;
    throw std::runtime_error(reason.str());
  }
}

// CLI11's NonNegativeNumber names the largest double in its message; this says it plainly.
std::string check_non_negative(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value) && value >= 0.0) return {};
  } catch (const std::exception&) {
  }
  return "'" + text + "' must be a number >= 0";
}

void install_listen(CLI::App& root) {
  auto options = std::make_shared<ListenOptions>();
  CLI::App* command = root.add_subcommand(
      "listen", "Print the cell's LCM messages (poses, status, profiles) as they arrive");
  command->add_option("--url", options->url, "LCM network to listen on")
      ->type_name("URL")
      ->capture_default_str();
  command
      ->add_option("--channel", options->channels,
                   "channel to print, repeatable (default: all three)")
      ->type_name("CHANNEL")
      ->check(CLI::IsMember(
          {std::string(kPoseChannel), std::string(kStatusChannel), std::string(kProfileChannel)}));
  command
      ->add_option("--count", options->count,
                   "exit after N messages; if the timeout comes first, fail (0: no limit)")
      ->type_name("N")
      ->check(check_non_negative, "NONNEGATIVE")
      ->capture_default_str();
  command->add_option("--timeout-s", options->timeout_s, "exit after S seconds (0: no limit)")
      ->type_name("S")
      ->check(check_non_negative, "NONNEGATIVE")
      ->capture_default_str();
  command->callback([options] { run_listen(*options); });
}

const CommandRegistration registration{"listen", install_listen};

}  // namespace
}  // namespace cosmos::cli
