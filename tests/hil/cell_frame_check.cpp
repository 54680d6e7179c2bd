#include "tests/hil/cell_frame_check.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace cosmos::hil {
namespace {

// The profiles just before and after a sequence number: the gap the cell saw there.
std::int64_t gap_at(const CellCheckContext& c, std::int64_t sequence) {
  const auto after = c.profile_sequences.lower_bound(sequence);
  if (after == c.profile_sequences.end() || after == c.profile_sequences.begin()) return -1;
  return *after - *std::prev(after) - 1;
}

}  // namespace

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

void check_frames(CellCheckContext& c, std::vector<ProbeCheck>& checks) {
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
  // Every frame that never became a profile is a lost profile: the frames vivid could not
  // fill and the corrupted one (delivered, flagged, requeued unseen), as the gaps in seq say.
  const std::int64_t unfilled = profile_gaps - corrupted_inside;
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
      unfilled == player_gaps && status_lost == profile_gaps && status_dropped == profile_gaps,
      "frames dropped: %lld sequence-number gaps in the profiles, %lld of them corrupted frames, "
      "the rest frames vivid could not fill (%lld by the player's count; the skip and the stall "
      "among them); COSMOS_STATUS profiles_lost %lld and profiles_dropped %lld",
      static_cast<long long>(profile_gaps), static_cast<long long>(corrupted_inside),
      static_cast<long long>(player_gaps), static_cast<long long>(status_lost),
      static_cast<long long>(status_dropped)));
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

void check_fault_traces(const CellCheckContext& c, std::vector<ProbeCheck>& checks) {
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
      checks.push_back(
          check_line(absent && c.corrupted.count(fault.observed) == 1,
                     "fault corrupt: frame %lld came with V4L2_BUF_FLAG_ERROR: %s, a lost profile",
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

}  // namespace cosmos::hil
