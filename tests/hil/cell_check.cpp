#include "tests/hil/cell_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "realtime/cell/part_recognition.hpp"
#include "sim/evaluation/add_s_distance.hpp"
#include "tests/hil/status_check.hpp"

namespace cosmos::hil {
namespace {

RigidPose rigid(const RigidTransform& T) { return {T.rotation, T.translation_mm}; }

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

struct Context {
  explicit Context(const CellRun& cell_run)
      : run(cell_run), tape(*cell_run.tape), player(*cell_run.player) {}
  const CellRun& run;
  const TapeHeader& tape;
  const PlayerLog& player;
  std::int64_t lead_in = 0;
  int ticks_per_frame = 4;
  double period_ns = 0;
  std::map<std::int64_t, std::int64_t> sequence_of_time_us;  // the cell's profiles
  std::set<std::int64_t> profile_sequences;
  std::set<std::int64_t> corrupted;
  std::map<std::int64_t, const PlayedCapture*> capture_of_sequence;
  std::vector<int> identified;  // per tape part
  int identified_count = 0;
  double add_s_median_percent = 0;
  std::int64_t sequence_gaps = 0;  // frames vivid could not fill
};

void check_parts(Context& c, std::vector<ProbeCheck>& checks) {
  std::map<std::string, std::unique_ptr<AddSDistance>> add_s;
  std::vector<double> percents;
  std::int64_t lag_min = 0, lag_max = 0, belt_off_min = 0, belt_off_max = 0;
  bool first_lag = true;
  c.identified.assign(c.tape.parts.size(), 0);
  const double step_mm = c.run.mm_per_tick * c.ticks_per_frame;
  for (const PartPose& pose : c.run.poses) {
    const auto found = c.sequence_of_time_us.find(pose.utime_us);
    if (found == c.sequence_of_time_us.end()) {
      checks.push_back(check_line(false, "pose %lld: its time stamp %lld us is no profile's",
                                  static_cast<long long>(pose.part_seq),
                                  static_cast<long long>(pose.utime_us)));
      continue;
    }
    const std::int64_t sequence = found->second;
    const std::int64_t profile = sequence - c.lead_in;
    // The last part to begin before the pose's last profile: a part completes some empty
    // rows after its end, never after the next part begins.
    int truth = -1;
    for (std::size_t i = 0; i < c.tape.parts.size(); ++i)
      if (c.tape.parts[i].first_profile <= profile) truth = static_cast<int>(i);
    if (truth < 0) {
      checks.push_back(info_line("pose %lld (%s) ends at frame %lld, before the first part",
                                 static_cast<long long>(pose.part_seq), pose.part_name.c_str(),
                                 static_cast<long long>(sequence)));
      continue;
    }
    const TapePart& part = c.tape.parts[static_cast<std::size_t>(truth)];
    const TapeModel* model = c.tape.model(part.name);
    if (model == nullptr) continue;
    auto& distance = add_s[part.name];
    if (!distance) distance = std::make_unique<AddSDistance>(model->points_mm);
    // The cell places the part along the belt by its frames' indices and publishes the pose
    // with its encoder count, so a robot tracking the belt from that count has the part where
    // the frame index put it: the estimate in the belt frame of count 0 (the count cancels).
    // The truth in that frame follows from the belt's true count of the pose's last frame
    // (the player's record) and the profile that frame stands for: when the belt was at
    // count E the part was where the conveyor had carried it by (s − L) profiles. A belt
    // that departs from ticks_per_frame per frame (held, slipping, started late) moves the
    // truth and shows as pose error; a count read late by the cell does not (it is harmless
    // to the robot, and the faults step checks the bridge's count at each frame).
    const auto capture = c.capture_of_sequence.find(sequence);
    const std::int64_t belt_tick = capture != c.capture_of_sequence.end()
                                       ? capture->second->belt_tick
                                       : sequence * c.ticks_per_frame;
    const RigidTransform T_belt_estimate =
        belt_pose_of(pose, c.run.T_cell_scanner, c.run.mm_per_tick);
    RigidTransform T_belt_true{part.T_belt_part.rotation(), part.T_belt_part.translation()};
    T_belt_true.translation_mm.y() -=
        static_cast<double>(belt_tick) * c.run.mm_per_tick - static_cast<double>(profile) * step_mm;
    const double error_mm = distance->add_s_mm(rigid(T_belt_true), rigid(T_belt_estimate));
    const double percent = 100.0 * error_mm / model->diameter_mm;
    const bool right =
        pose.status == PoseStatus::kOk && pose.part_name == part.name && percent < 10;
    const std::int64_t lag = pose.encoder_ticks - belt_tick;
    const std::int64_t belt_off = belt_tick - sequence * c.ticks_per_frame;
    lag_min = first_lag ? lag : std::min(lag_min, lag);
    lag_max = first_lag ? lag : std::max(lag_max, lag);
    belt_off_min = first_lag ? belt_off : std::min(belt_off_min, belt_off);
    belt_off_max = first_lag ? belt_off : std::max(belt_off_max, belt_off);
    first_lag = false;
    if (right) {
      c.identified[static_cast<std::size_t>(truth)] = 1;
      percents.push_back(percent);
    }
    // The part's frames as the cell got them: lost ones (no profile) and stale ones (a
    // profile of the frame before) distort its range image.
    std::int64_t lost = 0, stale = 0;
    for (std::int64_t s = c.lead_in + part.first_profile; s <= c.lead_in + part.last_profile; ++s)
      lost += c.profile_sequences.count(s) == 0 ? 1 : 0;
    for (const PlayedCapture& capture : c.player.captures) {
      const std::int64_t p = capture.sequence - c.lead_in;
      stale += capture.stale && p >= part.first_profile && p <= part.last_profile ? 1 : 0;
    }
    checks.push_back(info_line(
        "part %d (%s): the cell says %s %s (score %.3f), ADD-S %.2f mm = %.1f %% of its %.0f mm "
        "diameter, encoder %lld at frame %lld (%+lld ticks off the belt's); of its %lld frames "
        "%lld "
        "lost, %lld stale%s",
        truth, part.name.c_str(), pose.part_name.empty() ? "-" : pose.part_name.c_str(),
        to_string(pose.status), pose.score, error_mm, percent, model->diameter_mm,
        static_cast<long long>(pose.encoder_ticks), static_cast<long long>(sequence),
        static_cast<long long>(lag),
        static_cast<long long>(part.last_profile - part.first_profile + 1),
        static_cast<long long>(lost), static_cast<long long>(stale), right ? "" : "  <- wrong"));
  }
  const int parts = static_cast<int>(c.tape.parts.size());
  int identified = 0;
  for (const int one : c.identified) identified += one;
  const int required = static_cast<int>(std::ceil(c.run.required_fraction * parts - 1e-9));
  checks.push_back(check_line(
      identified >= required,
      "parts: %d of %d identified with ADD-S under 10 %% of the diameter (%d required); ADD-S "
      "median %.1f %%, worst %.1f %%; %zu poses; the cell's count at a part's last frame %+lld to "
      "%+lld ticks off the belt's, the belt's %+lld to %+lld off %d ticks a frame",
      identified, parts, required, median(percents),
      percents.empty() ? 0.0 : *std::max_element(percents.begin(), percents.end()),
      c.run.poses.size(), static_cast<long long>(lag_min), static_cast<long long>(lag_max),
      static_cast<long long>(belt_off_min), static_cast<long long>(belt_off_max),
      c.ticks_per_frame));
  c.identified_count = identified;
  c.add_s_median_percent = median(percents);
}

void check_frames(Context& c, std::vector<ProbeCheck>& checks) {
  const std::vector<Profile>& profiles = c.run.profiles;
  if (profiles.empty()) {
    checks.push_back(check_line(false, "frames: the cell published no profile"));
    return;
  }
  const std::int64_t first = static_cast<std::int64_t>(profiles.front().seq);
  const std::int64_t last = static_cast<std::int64_t>(profiles.back().seq);
  std::int64_t profile_gaps = first, corrupted_inside = 0, disorder = -1;
  for (std::size_t i = 1; i < profiles.size(); ++i) {
    profile_gaps += static_cast<std::int64_t>(profiles[i].seq - profiles[i - 1].seq) - 1;
    const bool in_order =
        profiles[i].seq > profiles[i - 1].seq && profiles[i].t_us > profiles[i - 1].t_us;
    if (!in_order && disorder < 0) disorder = static_cast<std::int64_t>(profiles[i].seq);
  }
  const bool monotonic = disorder < 0;
  for (const std::int64_t s : c.corrupted) corrupted_inside += s >= first && s <= last ? 1 : 0;
  std::int64_t captures_inside = 0, missing = 0, merged_inside = 0;
  std::vector<double> delays_ms;
  std::map<std::int64_t, std::int64_t> capture_time;
  for (const PlayedCapture& capture : c.player.captures)
    capture_time[capture.sequence] = capture.t_ns;
  for (const PlayedCapture& capture : c.player.captures) {
    if (capture.sequence < first || capture.sequence > last) continue;
    ++captures_inside;
    if (c.corrupted.count(capture.sequence) == 0 &&
        c.profile_sequences.count(capture.sequence) == 0)
      ++missing;
  }
  for (const std::int64_t s : c.player.merged) merged_inside += s >= first && s <= last ? 1 : 0;
  merged_inside += c.player.count("silent_first_fill");  // frame 0, filled without an event
  std::int64_t unknown = 0, first_unknown = -1;
  for (const Profile& profile : profiles) {
    const auto found = capture_time.find(static_cast<std::int64_t>(profile.seq));
    if (found == capture_time.end()) {
      if (unknown++ == 0) first_unknown = static_cast<std::int64_t>(profile.seq);
      continue;
    }
    const double delay_ns =
        static_cast<double>(profile.t_us) * 1000.0 - static_cast<double>(found->second);
    delays_ms.push_back(delay_ns / 1e6);
  }
  const std::int64_t player_gaps = (last - first + 1) - captures_inside - merged_inside + first;
  const std::int64_t dropped = profile_gaps - corrupted_inside;
  const std::int64_t status_dropped =
      c.run.statuses.empty() ? -1 : c.run.statuses.back().profiles_dropped;
  const std::int64_t status_acquired =
      c.run.statuses.empty() ? -1 : c.run.statuses.back().profiles_acquired;
  const std::int64_t status_lost =
      c.run.statuses.empty() ? -1 : c.run.statuses.back().profiles_lost;
  c.sequence_gaps = player_gaps;
  checks.push_back(check_line(
      monotonic && first == 0 && missing == 0 && unknown <= merged_inside &&
          status_acquired == static_cast<std::int64_t>(profiles.size()),
      "frames: %zu profiles with sequence numbers 0 to %lld, increasing with their time stamps "
      "(first out of order: %lld); "
      "of the %lld frames vivid filled for the camera %lld never became a profile (the "
      "corrupted one excepted), %lld profiles (the first %lld) came from fills the player saw "
      "only merged or without an event (%lld); COSMOS_STATUS profiles_acquired %lld",
      profiles.size(), static_cast<long long>(last), static_cast<long long>(disorder),
      static_cast<long long>(captures_inside), static_cast<long long>(missing),
      static_cast<long long>(unknown), static_cast<long long>(first_unknown),
      static_cast<long long>(merged_inside), static_cast<long long>(status_acquired)));
  checks.push_back(check_line(
      dropped == status_dropped && dropped == player_gaps && status_lost == player_gaps,
      "frames dropped: %lld sequence-number gaps in the profiles (%lld corrupted frame(s) not "
      "counted), COSMOS_STATUS profiles_lost %lld and profiles_dropped %lld, frames vivid could "
      "not fill %lld (the skip and the stall among them)",
      static_cast<long long>(dropped), static_cast<long long>(corrupted_inside),
      static_cast<long long>(status_lost), static_cast<long long>(status_dropped),
      static_cast<long long>(player_gaps)));
  // Time stamps on the capture's clock: vivid numbers a frame by the time its capture tick
  // ran and stamps it then, so a stamp lies within half a frame period (and a jiffy) of where
  // its number puts it, however late the tick; a frame period is allowed, for a guest CPU the
  // host preempted between the two. The fill the player saw follows the stamp's start by the
  // copy (informative only: a preempted guest stretches it).
  std::vector<double> offsets_ns;
  for (const Profile& profile : profiles)
    offsets_ns.push_back(static_cast<double>(profile.t_us) * 1000.0 -
                         static_cast<double>(profile.seq) * c.period_ns);
  const double reference_ns = median(offsets_ns);
  double worst_ns = 0;
  for (const double offset_ns : offsets_ns)
    worst_ns = std::max(worst_ns, std::abs(offset_ns - reference_ns));
  const double allowed_ns = c.period_ns;
  checks.push_back(check_line(
      worst_ns <= allowed_ns,
      "frame time stamps: every profile's t_us within %.1f ms of its sequence number's place on "
      "the capture clock (%.1f ms allowed: a frame period)",
      worst_ns / 1e6, allowed_ns / 1e6));
  const auto [shortest, longest] = std::minmax_element(delays_ms.begin(), delays_ms.end());
  checks.push_back(info_line(
      "frame time stamps: %.2f to %.2f ms (median %.2f) after the fill began that the player "
      "saw (%lld outside 0 to %.0f ms)",
      delays_ms.empty() ? 0.0 : *shortest, delays_ms.empty() ? 0.0 : *longest, median(delays_ms),
      static_cast<long long>(
          std::count_if(delays_ms.begin(), delays_ms.end(),
                        [&](double d) { return d < 0 || d > 2 * c.period_ns / 1e6; })),
      2 * c.period_ns / 1e6));
}

// The profiles just before and after a sequence number: the gap the cell saw there.
std::int64_t gap_at(const Context& c, std::int64_t sequence) {
  const auto after = c.profile_sequences.lower_bound(sequence);
  if (after == c.profile_sequences.end() || after == c.profile_sequences.begin()) return -1;
  return *after - *std::prev(after) - 1;
}

void check_faults(const Context& c, std::vector<ProbeCheck>& checks) {
  for (const PlayedFault& fault : c.player.faults) {
    const long long at = static_cast<long long>(fault.sequence);
    const std::int64_t seen = gap_at(c, fault.sequence);
    if (fault.kind == "skip" || fault.kind == "stall") {
      const bool watchdog = fault.kind == "skip" || fault.observed * c.period_ns > 2e8;
      checks.push_back(check_line(
          fault.observed > 0 && seen == fault.observed && watchdog,
          "fault %s at frame %lld: vivid delivered no frame for %lld frame periods, the cell's "
          "profiles show a gap of %lld there, counted as dropped",
          fault.kind.c_str(), at, static_cast<long long>(fault.observed),
          static_cast<long long>(seen)));
    } else if (fault.kind == "corrupt") {
      const bool absent = c.profile_sequences.count(fault.observed) == 0;
      checks.push_back(check_line(
          absent && c.corrupted.count(fault.observed) == 1,
          "fault corrupt: frame %lld came with V4L2_BUF_FLAG_ERROR: %s, and not counted as dropped",
          static_cast<long long>(fault.observed),
          absent ? "no profile made of it" : "made a profile"));
    } else {
      const auto after = c.profile_sequences.upper_bound(fault.sequence);
      checks.push_back(
          info_line("fault %s (%lld) at frame %lld: the cell went on, %lld profiles after it",
                    fault.kind.c_str(), static_cast<long long>(fault.amount), at,
                    static_cast<long long>(std::distance(after, c.profile_sequences.end()))));
    }
  }
  checks.push_back(info_line(
      "outputs: laser_enable on at %lld of %lld captures; result_ready pulses seen by sampling at "
      "each capture %lld, poses published %zu",
      static_cast<long long>(c.player.count("laser_on_captures")),
      static_cast<long long>(c.player.count("captures")),
      static_cast<long long>(c.player.count("result_ready_pulses")), c.run.poses.size()));
  checks.push_back(info_line(
      "player: %lld captures, %lld stale (the frame of an earlier sequence number: %lld after a "
      "gap, %lld queued too late, %lld not yet made the head by vivid's output thread), %lld "
      "encoder edges, %lld jiggles, %lld glitches, %lld beam arrivals (%lld bouncing), %lld "
      "edges gpio-cdev did not acknowledge, %lld frames not played (every output buffer queued)",
      static_cast<long long>(c.player.count("captures")),
      static_cast<long long>(c.player.count("stale_captures")),
      static_cast<long long>(c.player.count("stale_after_gap")),
      static_cast<long long>(c.player.count("stale_player_late")),
      static_cast<long long>(c.player.count("stale_output_late")),
      static_cast<long long>(c.player.count("encoder_edges")),
      static_cast<long long>(c.player.count("jiggles")),
      static_cast<long long>(c.player.count("glitches")),
      static_cast<long long>(c.player.count("beam_arrivals")),
      static_cast<long long>(c.player.count("bounced_arrivals")),
      static_cast<long long>(c.player.count("unacknowledged_edges")),
      static_cast<long long>(c.player.count("output_full_frames"))));
}

// The figures scripts/hil.sh repeats at the end of its run.
ProbeCheck summary_line(const Context& c) {
  const CellStatus last = c.run.statuses.empty() ? CellStatus{} : c.run.statuses.back();
  return info_line(
      "summary: %d of %zu parts identified, ADD-S median %.1f %%; %zu profiles, %lld frames "
      "lost (sequence gaps %lld); COSMOS_STATUS profiles_lost %lld, camera_timeouts %lld, "
      "encoder_errors %lld, encoder_reversals %lld, photo_eye_bounces %lld, gpio_edges_lost %lld",
      c.identified_count, c.tape.parts.size(), c.add_s_median_percent, c.run.profiles.size(),
      static_cast<long long>(last.profiles_lost), static_cast<long long>(c.sequence_gaps),
      static_cast<long long>(last.profiles_lost), static_cast<long long>(last.camera_timeouts),
      static_cast<long long>(last.encoder_errors), static_cast<long long>(last.encoder_reversals),
      static_cast<long long>(last.photo_eye_bounces), static_cast<long long>(last.gpio_edges_lost));
}

}  // namespace

std::vector<ProbeCheck> check_cell_run(const CellRun& run) {
  Context c(run);
  c.lead_in = run.player->plan.lead_in_frames;
  c.ticks_per_frame = run.player->plan.ticks_per_frame;
  c.period_ns = 1e9 / run.player->plan.capture_rate_hz;
  for (const Profile& profile : run.profiles) {
    c.sequence_of_time_us[profile.t_us] = static_cast<std::int64_t>(profile.seq);
    c.profile_sequences.insert(static_cast<std::int64_t>(profile.seq));
  }
  for (const PlayedFault& fault : run.player->faults)
    if (fault.kind == "corrupt") c.corrupted.insert(fault.observed);
  for (const PlayedCapture& capture : run.player->captures)
    c.capture_of_sequence[capture.sequence] = &capture;
  std::vector<ProbeCheck> checks;
  check_parts(c, checks);
  check_frames(c, checks);
  check_faults(c, checks);
  const int parts = static_cast<int>(c.tape.parts.size());
  StatusRun status_run;
  status_run.statuses = &run.statuses;
  status_run.player = run.player;
  status_run.tape = run.tape;
  status_run.profile_sequences = &c.profile_sequences;
  status_run.identified = &c.identified;
  status_run.misses_allowed =
      parts - static_cast<int>(std::ceil(run.required_fraction * parts - 1e-9));
  for (ProbeCheck& check : check_status_faults(status_run)) checks.push_back(std::move(check));
  checks.push_back(summary_line(c));
  return checks;
}

}  // namespace cosmos::hil
