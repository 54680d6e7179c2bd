#include "tests/hil/bridge_probe.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <thread>

#include "firmware_bridge/gpio_lines.hpp"
#include "firmware_bridge/v4l2_camera.hpp"
#include "realtime/sources/hardware_source.hpp"
#include "tests/hil/player_log.hpp"

namespace cosmos::hil {
namespace {

namespace fs = std::filesystem;

struct Seen {
  std::int64_t sequence = 0;
  std::int64_t t_us = 0;
  std::int64_t ticks = 0;
};

bool wait_for(const fs::path& file, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!fs::exists(file)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return true;
}

std::int64_t median_of(std::vector<std::int64_t> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

const PlayedFault* fault_of(const PlayerLog& log, const char* kind) {
  for (const PlayedFault& fault : log.faults)
    if (fault.kind == kind) return &fault;
  return nullptr;
}

}  // namespace

std::vector<ProbeCheck> probe_bridge(const BridgeProbeSettings& settings) {
  std::vector<ProbeCheck> checks;
  if (!wait_for(settings.plan_file, settings.wait_s)) {
    checks.push_back(check_line(false, "bridge: the player made no plan"));
    return checks;
  }
  const PlayerPlan plan = read_player_log(settings.plan_file).plan;
  V4l2Camera camera(settings.hardware.camera);
  LibgpiodLines gpio(settings.hardware.gpio);
  HardwareSource source(settings.hardware, settings.scanner, camera, gpio);
  if (source.start() != SourceStatus::kOk) {
    checks.push_back(check_line(false, "bridge: start: %.*s",
                                static_cast<int>(source.last_error().size()),
                                source.last_error().data()));
    return checks;
  }
  Profile profile;
  source.reserve(profile);
  std::vector<Seen> seen;
  std::int64_t timeouts_seen = 0, frames_after_timeout = 0;
  const std::int64_t last_wanted =
      plan.end_sequence + static_cast<std::int64_t>(plan.capture_rate_hz);
  const auto deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration<double>(settings.wait_s + last_wanted / plan.capture_rate_hz);
  while (std::chrono::steady_clock::now() < deadline) {
    const SourceStatus status = source.next(profile);
    if (status == SourceStatus::kTimeout) {
      ++timeouts_seen;
      continue;
    }
    if (status != SourceStatus::kOk) {
      checks.push_back(check_line(false, "bridge: next: %.*s",
                                  static_cast<int>(source.last_error().size()),
                                  source.last_error().data()));
      break;
    }
    if (timeouts_seen > 0) ++frames_after_timeout;
    seen.push_back({static_cast<std::int64_t>(profile.seq), profile.t_us, profile.encoder_ticks});
    if (static_cast<std::int64_t>(profile.seq) >= last_wanted) break;
  }
  const CameraStats stats = camera.stats();
  const EncoderCounts encoder = gpio.decoder().encoder_counts();
  const PhotoEyeCounts eye = gpio.decoder().photo_eye_counts();
  const PhotoEyeTally tally = source.photo_eye();
  const std::uint64_t lost_edges = gpio.lost_edges();
  source.stop();
  if (!wait_for(settings.player_log, settings.wait_s)) {
    checks.push_back(check_line(false, "bridge: the player wrote no log"));
    return checks;
  }
  const PlayerLog log = read_player_log(settings.player_log);
  if (seen.empty()) {
    checks.push_back(check_line(false, "bridge: no profile"));
    return checks;
  }

  // Frames: every fill the player saw is a profile of its number, but the corrupted one.
  const PlayedFault* corrupt = fault_of(log, "corrupt");
  const std::int64_t first = seen.front().sequence, last = seen.back().sequence;
  std::map<std::int64_t, std::int64_t> fill_time;
  for (const PlayedCapture& capture : log.captures) fill_time[capture.sequence] = capture.t_ns;
  std::set<std::int64_t> profiles;
  std::int64_t unknown = 0, late = 0;
  const double period_ns = 1e9 / plan.capture_rate_hz;
  for (const Seen& s : seen) {
    profiles.insert(s.sequence);
    const auto fill = fill_time.find(s.sequence);
    if (fill == fill_time.end()) {
      ++unknown;
      continue;
    }
    const double delay_ns =
        static_cast<double>(s.t_us) * 1000.0 - static_cast<double>(fill->second);
    late += delay_ns < 0 || delay_ns > 2 * period_ns ? 1 : 0;
  }
  std::int64_t fills = 0, missing = 0;
  for (const PlayedCapture& capture : log.captures) {
    if (capture.sequence < first || capture.sequence > last) continue;
    ++fills;
    const bool corrupted = corrupt != nullptr && capture.sequence == corrupt->observed;
    missing += !corrupted && profiles.count(capture.sequence) == 0 ? 1 : 0;
  }
  const std::int64_t unseen = log.count("merged_events") + log.count("silent_first_fill");
  const std::int64_t gaps = (last - first + 1) - fills - unseen + first;
  checks.push_back(check_line(
      missing == 0 && unknown <= unseen && late == 0 && stats.frames == seen.size(),
      "bridge frames: %zu profiles of frames %lld to %lld through HardwareSource, each with "
      "its sequence number and a time stamp within a frame period of its number's place on "
      "the capture clock (%lld not); %lld fills without a profile (the corrupted one "
      "excepted)",
      seen.size(), static_cast<long long>(first), static_cast<long long>(last),
      static_cast<long long>(late), static_cast<long long>(missing)));
  const PlayedFault* skip = fault_of(log, "skip");
  checks.push_back(check_line(
      static_cast<std::int64_t>(stats.dropped_frames) == gaps && skip != nullptr &&
          skip->observed == skip->amount &&
          source.health().profiles_lost == stats.dropped_frames + stats.corrupted_frames,
      "bridge dropped: the camera counted %llu dropped frames and %llu corrupted ones, the source "
      "%llu lost profiles, vivid left %lld sequence gaps; the skip of %lld frames left a gap of "
      "%lld",
      static_cast<unsigned long long>(stats.dropped_frames),
      static_cast<unsigned long long>(stats.corrupted_frames),
      static_cast<unsigned long long>(source.health().profiles_lost), static_cast<long long>(gaps),
      static_cast<long long>(skip ? skip->amount : -1),
      static_cast<long long>(skip ? skip->observed : -1)));
  const PlayedFault* stall = fault_of(log, "stall");
  checks.push_back(check_line(
      stall != nullptr && stats.timeouts >= 1 && timeouts_seen >= 1 && frames_after_timeout > 0,
      "bridge stall: %lld ms without frames (%lld frame periods): %llu watchdog timeouts of %lld "
      "ms counted by the camera, %lld seen by the source, %lld frames after them",
      static_cast<long long>(stall ? stall->amount : -1),
      static_cast<long long>(stall ? stall->observed : -1),
      static_cast<unsigned long long>(stats.timeouts),
      static_cast<long long>(settings.hardware.frame_timeout_us / 1000),
      static_cast<long long>(timeouts_seen), static_cast<long long>(frames_after_timeout)));
  checks.push_back(check_line(
      corrupt != nullptr && stats.corrupted_frames == 1 && profiles.count(corrupt->observed) == 0,
      "bridge corrupt: frame %lld flagged V4L2_BUF_FLAG_ERROR: %llu corrupted frame(s) counted, "
      "no profile of it, not counted as dropped",
      static_cast<long long>(corrupt ? corrupt->observed : -1),
      static_cast<unsigned long long>(stats.corrupted_frames)));

  // Encoder: the count at each frame against the count the belt had driven onto the lines
  // when that frame was exposed (the player's record), before the first encoder fault and
  // after the last: the bridge must count what the lines did, however well the player's
  // belt kept pace with the capture clock (printed beside it).
  const PlayedFault* jiggle = fault_of(log, "jiggle");
  const PlayedFault* glitch = fault_of(log, "glitch");
  std::map<std::int64_t, std::int64_t> belt_tick;
  for (const PlayedCapture& capture : log.captures) belt_tick[capture.sequence] = capture.belt_tick;
  // The first second is left out: the belt is held until the lines are requested.
  const auto settled = static_cast<std::int64_t>(plan.capture_rate_hz);
  std::vector<std::int64_t> lag_before, lag_after, belt_off;
  for (const Seen& s : seen) {
    const auto belt = belt_tick.find(s.sequence);
    if (s.sequence < settled || belt == belt_tick.end()) continue;
    const std::int64_t lag = s.ticks - belt->second;
    belt_off.push_back(belt->second - s.sequence * plan.ticks_per_frame);
    if (jiggle && s.sequence < jiggle->sequence) lag_before.push_back(lag);
    if (glitch && s.sequence > glitch->sequence + 2) lag_after.push_back(lag);
  }
  const std::int64_t before = median_of(lag_before), after = median_of(lag_after);
  // The count is read after the frame arrives, as from a free-running camera: a few ticks
  // late at most, and no later after the faults than before.
  const bool on_the_belt = !lag_before.empty() && !lag_after.empty() &&
                           std::abs(before) <= plan.ticks_per_frame &&
                           std::abs(after - before) <= 2;
  const bool glitch_seen = encoder.reversals >= 4 || encoder.invalid_transitions >= 1;
  checks.push_back(check_line(
      jiggle != nullptr && glitch != nullptr && encoder.reversals >= 2 && glitch_seen &&
          on_the_belt && lost_edges == 0,
      "bridge encoder: %lld steps, %llu reversals (the %lld-tick jiggle makes 2), %llu invalid "
      "transitions and %llu ignored edges (the glitch makes 1 invalid or 2 reversals); count "
      "minus the belt's at each frame: median %+lld ticks before the faults, %+lld after; %llu "
      "edges lost; the belt's count %+lld ticks (median) off %d a frame",
      static_cast<long long>(encoder.steps), static_cast<unsigned long long>(encoder.reversals),
      static_cast<long long>(jiggle ? jiggle->amount : -1),
      static_cast<unsigned long long>(encoder.invalid_transitions),
      static_cast<unsigned long long>(encoder.ignored_edges), static_cast<long long>(before),
      static_cast<long long>(after), static_cast<unsigned long long>(lost_edges),
      static_cast<long long>(median_of(belt_off)), plan.ticks_per_frame));
  const std::int64_t beam = log.count("beam_arrivals");
  const std::uint64_t filtered = eye.bounces + eye.rejected_pulses + eye.bridged_gaps;
  checks.push_back(check_line(
      static_cast<std::int64_t>(tally.arrivals) == beam &&
          static_cast<std::int64_t>(tally.departures) == beam &&
          log.count("bounced_arrivals") > 0 && filtered >= 1,
      "bridge photo eye: %llu arrivals and %llu departures for %lld parts; %llu edges, of them "
      "%llu bounces, %llu rejected pulses, %llu bridged gaps (%lld arrival(s) bounced)",
      static_cast<unsigned long long>(tally.arrivals),
      static_cast<unsigned long long>(tally.departures), static_cast<long long>(beam),
      static_cast<unsigned long long>(eye.edges), static_cast<unsigned long long>(eye.bounces),
      static_cast<unsigned long long>(eye.rejected_pulses),
      static_cast<unsigned long long>(eye.bridged_gaps),
      static_cast<long long>(log.count("bounced_arrivals"))));
  return checks;
}

}  // namespace cosmos::hil
