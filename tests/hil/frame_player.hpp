#pragma once
// The HIL frame player: plays the simulated conveyor's frames, recorded on the host
// (frame_tape.hpp), into vivid's output node so that the cell's camera, on the capture node,
// sees the frames a real camera would see of the parts passing, one conveyor profile per
// capture frame.
//
// Capture frame s shows profile s − L, L frames of empty belt (the lead-in) giving the cell
// time to start, and the empty belt again after the conveyor's last profile. vivid's capture
// runs on its own clock and copies whatever frame heads the output queue, so the player
// follows it: at each capture it learns of (CaptureTicks) it queues the frame for the next
// sequence number behind the head, and vivid's faster output thread makes that the head
// before the next capture. Frames the capture could not deliver (no free buffer, dropped)
// still advance the sequence, and the belt with it, as on a free-running camera.
//
// Faults at chosen profiles (put into empty belt by the caller, so they cost no part):
//   skip N     vivid drops the next N captures ("Percentage of Dropped Buffers" at 100):
//              a sequence gap of N frames the camera must count as dropped;
//   stall MS   the same for MS milliseconds, longer than the camera's watchdog;
//   jiggle N, glitch, bounce K   the encoder's and photo eye's (encoder_player.hpp);
//   corrupt    the next capture is returned with V4L2_BUF_FLAG_ERROR.
// Stops once the conveyor has been played and the capture has been idle for a while (the
// cell stopped), and writes its log (player_log.hpp).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "realtime/config/hardware_config.hpp"
#include "tests/hil/encoder_player.hpp"
#include "tests/hil/frame_tape.hpp"
#include "tests/hil/player_log.hpp"
#include "tests/hil/vivid_loop.hpp"

namespace cosmos::hil {

struct FaultAt {
  std::string kind;          // skip, stall, jiggle, glitch, corrupt (bounce: EncoderPlayer)
  std::int64_t profile = 0;  // the conveyor profile it comes at
  std::int64_t amount = 0;
};

struct FramePlayerSettings {
  std::string capture_node = "/dev/video0";
  std::string output_node = "/dev/video1";
  VividLoopSettings loop;
  double lead_in_s = 12.0;  // longer than the cell takes to start (its model base, under TCG)
  double tail_s = 2.0;      // empty belt played after the last profile, in the cell's duration
  std::vector<FaultAt> faults;
  std::vector<std::size_t> bouncing_arrivals;
  std::filesystem::path plan_file;  // written once the plan is known
  double idle_limit_s = 90.0;       // no capture for this long: the cell is gone
};

// Plays until done; returns the log (also the caller's to write).
PlayerLog play_conveyor(FrameTapeReader& tape, GpioSimLines& lines, const HardwareConfig& hardware,
                        const FramePlayerSettings& settings);

}  // namespace cosmos::hil
