#pragma once
// What the HIL player did, for the checks that compare it with what the cell saw: the plan
// (lead-in, conveyor length, where the stream ends), every frame the capture side was given
// (its sequence number, when, and which conveyor profile it showed), the faults injected and
// what they did, and the player's counters. One text line per record:
//   plan LEAD_IN CONVEYOR_FRAMES END_SEQUENCE RATE_HZ TICKS_PER_FRAME CELL_DURATION_S
//   capture SEQUENCE T_NS CONTENT STALE BELT_TICK   (CONTENT: conveyor profile, -1 empty belt)
//   merged SEQUENCE                         (a fill whose event the player did not see)
//   fault KIND SEQUENCE AMOUNT OBSERVED
//   count NAME VALUE
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace cosmos::hil {

struct PlayerPlan {
  std::int64_t lead_in_frames = 0;   // frames of empty belt before the conveyor's profile 0
  std::int64_t conveyor_frames = 0;  // profiles 0 … conveyor_frames − 1
  std::int64_t end_sequence = 0;     // the capture sequence the conveyor's last profile shows at
  double capture_rate_hz = 0;
  int ticks_per_frame = 4;
  double cell_duration_s = 0;  // data time the cell needs to see every profile
};

struct PlayedCapture {
  std::int64_t sequence = 0;
  std::int64_t t_ns = 0;     // when vivid began filling it (CLOCK_MONOTONIC)
  std::int64_t content = 0;  // conveyor profile shown, -1 the empty belt
  bool stale = false;        // not the profile its sequence number stands for
  // The count the player's belt had driven onto the encoder lines at t_ns: the belt's true
  // count of this frame (the sequence number times ticks_per_frame only while the belt keeps
  // pace with the capture clock).
  std::int64_t belt_tick = 0;
};

// skip: AMOUNT frames dropped by vivid (OBSERVED: the sequence gap that followed);
// stall: AMOUNT ms without frames (OBSERVED: the gap); jiggle: AMOUNT ticks back and forth;
// glitch: a pulse on encoder A; bounce: the beam bounces at arrival AMOUNT (a part index);
// corrupt: a capture flagged V4L2_BUF_FLAG_ERROR (OBSERVED: its sequence number).
struct PlayedFault {
  std::string kind;
  std::int64_t sequence = 0;
  std::int64_t amount = 0;
  std::int64_t observed = -1;
};

struct PlayerLog {
  PlayerPlan plan;
  std::vector<PlayedCapture> captures;
  std::vector<std::int64_t> merged;  // sequence numbers of fills seen only as merged events
  std::vector<PlayedFault> faults;
  std::map<std::string, std::int64_t> counts;

  std::int64_t count(const std::string& name) const {
    const auto found = counts.find(name);
    return found == counts.end() ? 0 : found->second;
  }
};

void write_player_plan(const std::filesystem::path& file, const PlayerPlan& plan);
void write_player_log(const std::filesystem::path& file, const PlayerLog& log);
// Throws std::runtime_error naming the file and line when it does not parse.
PlayerLog read_player_log(const std::filesystem::path& file);

}  // namespace cosmos::hil
