#include "tests/hil/status_check.hpp"

#include <algorithm>
#include <iterator>
#include <string>
#include <string_view>

#include "realtime/cell/cell_state_rule.hpp"

namespace cosmos::hil {
namespace {

bool is_camera_timeout(const CellStatus& status) {
  return status.state == CellState::kFault &&
         status.state_text.find("camera timeout") != std::string::npos;
}

const PlayedFault* played(const PlayerLog& player, const char* kind) {
  for (const PlayedFault& fault : player.faults)
    if (fault.kind == kind) return &fault;
  return nullptr;
}

// The fault totals (cell_state_rule.hpp) the played faults grow. Frames lost are always
// explained: vivid fills no frame for a skip or a stall, nor when it runs late, and
// cell_check accounts every gap. A corrupted frame may hold no stripe at all (laser off).
std::set<std::string_view> explained_totals(const PlayerLog& player) {
  std::set<std::string_view> explained = {"frames lost"};
  const auto explain = [&](const char* what) { explained.insert(what); };
  if (played(player, "stall") != nullptr) explain("camera timeouts");
  if (played(player, "jiggle") != nullptr || played(player, "glitch") != nullptr) {
    explain("encoder reversals");
    explain("encoder errors");
  }
  if (player.count("bounced_arrivals") > 0) explain("photo-eye bounces");
  if (played(player, "corrupt") != nullptr) explain("profiles without laser light (laser off)");
  return explained;
}

// What of a FAULT message the played faults do not explain: the totals that grew since the
// message before it and are none of `explained`, or a reason that is neither a stall nor a
// grown total (the source failed). Empty: explained, or not a FAULT.
std::string unexplained_fault(const CellStatus* previous, const CellStatus& status,
                              const std::set<std::string_view>& explained, bool stall_played) {
  if (status.state != CellState::kFault) return {};
  std::string out;
  bool grew = false;
  for (const FaultTotal& fault : fault_totals()) {
    const std::int64_t added = status.*fault.total - (previous ? previous->*fault.total : 0);
    if (added <= 0) continue;
    grew = true;
    if (explained.count(fault.what) == 0)
      out += (out.empty() ? "" : ", ") + std::to_string(added) + ' ' + fault.what;
  }
  const bool stall = status.state_text.rfind(kCameraStallReason, 0) == 0;
  if ((stall && !stall_played) || (!stall && !grew))
    out += (out.empty() ? "" : ", ") + status.state_text;
  return out;
}

void check_stall(const StatusRun& run, const PlayedFault* stall, std::vector<ProbeCheck>& checks) {
  const std::vector<CellStatus>& statuses = *run.statuses;
  const std::set<std::string_view> explained = explained_totals(*run.player);
  std::int64_t fault_runs = 0, fault_messages = 0, other_faults = 0;
  std::string first_unexplained;
  for (std::size_t i = 0; i < statuses.size(); ++i) {
    const bool fault = statuses[i].state == CellState::kFault;
    fault_messages += fault ? 1 : 0;
    fault_runs += fault && (i == 0 || statuses[i - 1].state != CellState::kFault) ? 1 : 0;
    const std::string why = unexplained_fault(i > 0 ? &statuses[i - 1] : nullptr, statuses[i],
                                              explained, stall != nullptr);
    if (why.empty()) continue;
    ++other_faults;
    if (first_unexplained.empty()) first_unexplained = why;
  }
  const std::int64_t timeouts = statuses.empty() ? 0 : statuses.back().camera_timeouts;
  if (stall == nullptr) {
    checks.push_back(
        check_line(other_faults == 0,
                   "COSMOS_STATUS: no stall played, %lld FAULT messages, %lld not "
                   "explained by the played faults%s%s",
                   static_cast<long long>(fault_messages), static_cast<long long>(other_faults),
                   first_unexplained.empty() ? "" : ", the first: ", first_unexplained.c_str()));
    return;
  }
  // The profiles before the stall's gap (the first gap from the frame before the stall
  // began): what the loop had processed while it waited.
  const std::set<std::int64_t>& sequences = *run.profile_sequences;
  auto last_before = sequences.lower_bound(stall->sequence - 1);
  while (last_before != sequences.end() && std::next(last_before) != sequences.end() &&
         *std::next(last_before) == *last_before + 1)
    ++last_before;
  const auto before_gap =
      last_before == sequences.end()
          ? -1
          : static_cast<std::int64_t>(std::distance(sequences.begin(), last_before)) + 1;
  std::int64_t during = 0, timeouts_during = 0;
  std::size_t last_during = statuses.size();
  for (std::size_t i = 0; i < statuses.size(); ++i) {
    if (!is_camera_timeout(statuses[i]) || statuses[i].profiles_acquired != before_gap) continue;
    ++during;
    timeouts_during = std::max(timeouts_during, statuses[i].camera_timeouts);
    last_during = i;
  }
  bool resumed = false;
  for (std::size_t i = last_during; i < statuses.size() && !resumed; ++i)
    resumed =
        statuses[i].state == CellState::kScanning && statuses[i].profiles_acquired > before_gap;
  checks.push_back(check_line(
      timeouts >= 1 && during >= 1 && timeouts_during >= 1 && resumed && other_faults == 0,
      "COSMOS_STATUS stall at frame %lld (%lld frame periods without frames): camera_timeouts "
      "%lld at the end; %lld FAULT message(s) \"camera timeout\" while the cell waited after its "
      "%lld profiles before the gap (camera_timeouts %lld there), SCANNING again after it %s; "
      "%lld FAULT message(s) in %lld run(s) in all, %lld not explained by the played faults%s%s",
      static_cast<long long>(stall->sequence), static_cast<long long>(stall->observed),
      static_cast<long long>(timeouts), static_cast<long long>(during),
      static_cast<long long>(before_gap), static_cast<long long>(timeouts_during),
      resumed ? "yes" : "no", static_cast<long long>(fault_messages),
      static_cast<long long>(fault_runs), static_cast<long long>(other_faults),
      first_unexplained.empty() ? "" : ", the first: ", first_unexplained.c_str()));
  // The cell recovers: the parts that came after the stall are identified.
  const std::int64_t stall_profile = stall->sequence - run.player->plan.lead_in_frames;
  int later = 0, later_identified = 0;
  for (std::size_t i = 0; i < run.tape->parts.size(); ++i) {
    if (run.tape->parts[i].first_profile <= stall_profile) continue;
    ++later;
    later_identified += (*run.identified)[i];
  }
  checks.push_back(check_line(later > 0 && later_identified >= later - run.misses_allowed,
                              "recovery: %d of the %d parts after the stall identified",
                              later_identified, later));
}

}  // namespace

std::vector<ProbeCheck> check_status_faults(const StatusRun& run) {
  std::vector<ProbeCheck> checks;
  const std::vector<CellStatus>& statuses = *run.statuses;
  const PlayerLog& player = *run.player;
  if (statuses.empty()) {
    checks.push_back(check_line(false, "COSMOS_STATUS: the cell published no status"));
    return checks;
  }
  check_stall(run, played(player, "stall"), checks);
  const CellStatus& last = statuses.back();
  const std::int64_t jiggle_reversals = player.count("jiggle_reversals");
  if (played(player, "jiggle") != nullptr || played(player, "glitch") != nullptr) {
    // The glitch: one invalid transition, or both of its edges seen as two reversals.
    const bool glitch_seen = played(player, "glitch") == nullptr || last.encoder_errors >= 1 ||
                             last.encoder_reversals >= jiggle_reversals + 2;
    checks.push_back(check_line(
        last.encoder_reversals >= jiggle_reversals && glitch_seen,
        "COSMOS_STATUS encoder: encoder_reversals %lld (the %lld jiggle(s) make %lld), "
        "encoder_errors %lld (the %lld glitch(es) make 1 error or 2 reversals each), "
        "gpio_edges_lost %lld",
        static_cast<long long>(last.encoder_reversals),
        static_cast<long long>(player.count("jiggles")), static_cast<long long>(jiggle_reversals),
        static_cast<long long>(last.encoder_errors),
        static_cast<long long>(player.count("glitches")),
        static_cast<long long>(last.gpio_edges_lost)));
  }
  if (player.count("bounced_arrivals") > 0) {
    checks.push_back(check_line(last.photo_eye_bounces >= 1,
                                "COSMOS_STATUS photo eye: photo_eye_bounces %lld for %lld bouncing "
                                "arrival(s)",
                                static_cast<long long>(last.photo_eye_bounces),
                                static_cast<long long>(player.count("bounced_arrivals"))));
  }
  checks.push_back(check_line(last.state == CellState::kIdle,
                              "COSMOS_STATUS end: %zu messages, the last %s (\"%s\")",
                              statuses.size(), to_string(last.state), last.state_text.c_str()));
  return checks;
}

}  // namespace cosmos::hil
