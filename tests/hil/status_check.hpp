#pragma once
// The HIL cell run's faults as COSMOS_STATUS reported them, message by message, against what
// the player injected (player_log.hpp): the totals a robot cell's operator reads, not the
// bridge's own counters (the faults step reads those).
//
//   stall     a wait longer than the camera's watchdog: camera_timeouts >= 1, and FAULT with
//             the camera-timeout reason while it lasts, tied to the stall by profiles_acquired
//             (during a stall the loop has processed exactly the profiles before its gap);
//             then SCANNING again with more profiles, and the parts after it identified;
//   jiggle    the belt backing up and coming forward: its reversals in encoder_reversals;
//   glitch    a pulse on encoder A shorter than gpio-cdev resolves: an encoder_errors count,
//             or two more reversals when the interrupt thread was quick enough for both edges;
//   bounce    the photo eye bouncing at a part's arrival: photo_eye_bounces >= 1;
//   the end   the last status IDLE, and no FAULT the played faults do not explain: each FAULT
//             message is read against the one before it, the totals that grew between them
//             (cell_state_rule.hpp's fault totals) must be ones the played faults grow.
// The frame losses (profiles_lost = the sequence gaps) are cell_check's frame accounting.
#include <cstdint>
#include <set>
#include <vector>

#include "realtime/cell/cell_status.hpp"
#include "tests/hil/check_line.hpp"
#include "tests/hil/frame_tape.hpp"
#include "tests/hil/player_log.hpp"

namespace cosmos::hil {

struct StatusRun {
  const std::vector<CellStatus>* statuses = nullptr;  // in the order they were published
  const PlayerLog* player = nullptr;
  const TapeHeader* tape = nullptr;
  const std::set<std::int64_t>* profile_sequences = nullptr;  // the cell's profiles
  const std::vector<int>* identified = nullptr;               // per tape part, 1 when right
  int misses_allowed = 1;  // parts the whole run may miss (cell_check's required fraction)
};

std::vector<ProbeCheck> check_status_faults(const StatusRun& run);

}  // namespace cosmos::hil
