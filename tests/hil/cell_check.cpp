#include "tests/hil/cell_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "realtime/cell/part_recognition.hpp"
#include "sim/evaluation/add_s_distance.hpp"
#include "tests/hil/cell_frame_check.hpp"
#include "tests/hil/status_check.hpp"

namespace cosmos::hil {
namespace {

RigidPose rigid(const RigidTransform& T) { return {T.rotation, T.translation_mm}; }

void check_parts(CellCheckContext& c, std::vector<ProbeCheck>& checks) {
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
        "%lld lost, %lld stale%s",
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

// The figures scripts/hil.sh repeats at the end of its run.
ProbeCheck summary_line(const CellCheckContext& c) {
  const CellStatus last = c.run.statuses.empty() ? CellStatus{} : c.run.statuses.back();
  return info_line(
      "summary: %d of %zu parts identified, ADD-S median %.1f %%; %zu profiles, %lld sequence "
      "gaps (frames vivid could not fill); COSMOS_STATUS profiles_lost %lld, camera_timeouts %lld, "
      "encoder_errors %lld, encoder_reversals %lld, photo_eye_bounces %lld, gpio_edges_lost %lld",
      c.identified_count, c.tape.parts.size(), c.add_s_median_percent, c.run.profiles.size(),
      static_cast<long long>(c.sequence_gaps), static_cast<long long>(last.profiles_lost),
      static_cast<long long>(last.camera_timeouts), static_cast<long long>(last.encoder_errors),
      static_cast<long long>(last.encoder_reversals),
      static_cast<long long>(last.photo_eye_bounces), static_cast<long long>(last.gpio_edges_lost));
}

}  // namespace

std::vector<ProbeCheck> check_cell_run(const CellRun& run) {
  CellCheckContext c(run);
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
  check_fault_traces(c, checks);
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
