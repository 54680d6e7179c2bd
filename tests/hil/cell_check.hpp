#pragma once
// The verdict on a `cosmos cell` run inside the HIL guest, from what the cell published over
// LCM (its poses, status messages and profiles, recorded by lcm-logger), what the player did
// (player_log.hpp) and the conveyor's ground truth (frame_tape.hpp).
//
//   parts    at least required_fraction of the conveyor's parts identified with a pose within
//            ADD-S 10 % of the part's diameter. A pose is judged as a robot tracking the belt
//            from the pose's encoder count would use it, against the part's truth at the
//            belt's true count of the pose's last frame (what the player's belt had driven
//            onto the lines at that frame's exposure, player_log.hpp): the cell places a part
//            by its frames' indices, so the frame index, the belt and the stripe all have to
//            agree (docs/hil.md, "Where a pose is judged").
//   frames   every frame the capture side was given reached the cell as a profile of that
//            sequence number with its time stamp (within two frame periods after the fill
//            began), except the one flagged corrupted; the gaps in the profiles' sequence
//            numbers are the frames vivid could not fill and the corrupted one, and
//            COSMOS_STATUS profiles_lost and profiles_dropped equal them.
//   faults   each injected fault shows where it should (the skip's and the stall's gaps, the
//            corrupted frame missing, a lost profile but no dropped camera frame) and the cell ran
//            on to the end; on COSMOS_STATUS as status_check.hpp says.
// The last line is a summary of the figures (scripts/hil.sh repeats it).
#include <vector>

#include "core/profile.hpp"
#include "core/rigid_transform.hpp"
#include "realtime/cell/cell_status.hpp"
#include "realtime/cell/part_pose.hpp"
#include "tests/hil/check_line.hpp"
#include "tests/hil/frame_tape.hpp"
#include "tests/hil/player_log.hpp"

namespace cosmos::hil {

struct CellRun {
  const TapeHeader* tape = nullptr;
  const PlayerLog* player = nullptr;
  std::vector<PartPose> poses;
  std::vector<CellStatus> statuses;
  std::vector<Profile> profiles;
  RigidTransform T_cell_scanner;
  double mm_per_tick = 0.1;
  double required_fraction = 0.9;
};

std::vector<ProbeCheck> check_cell_run(const CellRun& run);

}  // namespace cosmos::hil
