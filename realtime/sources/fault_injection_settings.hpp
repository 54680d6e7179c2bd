#pragma once
// The `faults:` section: faults the simulated cell injects into itself (sim/source/fault_plan.hpp
// places them), so that the cell's detection, counting and recovery can be tried without
// breaking hardware. Every fault is off by default; each one that is on recurs, once in every
// run of `every_profiles` profiles (camera frames), at a place in that run drawn from `seed`,
// and lasts `profiles` profiles. Declared here, beside the sources, so that the cell config
// reads it (realtime/ does not see sim/).
//
// Which source injects what:
//   simulated source  frame gaps, camera stalls (timeouts), encoder glitches, reversals and
//                     a stuck encoder (on the profile's encoder count), laser off
//   hardware twins    the same at the devices: the camera loses frames, stalls for longer
//                     than the watchdog or images the belt with the laser off; the encoder's
//                     lines miss an edge, run backwards or freeze; the photo eye bounces
//   the cell          recognizer_delay_ms slows the recognizer into overload;
//                     corrupt_model_base damages the model base as it is read at start
// The faults are never reported by the simulators themselves beyond what the real device
// would report: the cell finds a stuck encoder or a dark laser in the data
// (realtime/sources/stream_checked_source.hpp).
#include <cstdint>

#include "core/parameter_visitor.hpp"

namespace cosmos {

struct FaultSchedule {
  int every_profiles = 0;  // 0: off
  int profiles = 1;        // length of each occurrence (clamped to every_profiles)

  bool on() const { return every_profiles > 0; }

  template <class Visitor>
  void visit(Visitor& v) {
    v("every_profiles", every_profiles,
      "one occurrence in each run of this many profiles, at a seeded place; 0: off", Range{0, 1e9});
    v("profiles", profiles, "profiles each occurrence lasts", Range{1, 1e9});
  }
};

struct FaultInjectionSettings {
  std::uint64_t seed = 1;
  FaultSchedule frame_gaps;         // frames the camera loses (seq jumps)
  FaultSchedule camera_stalls;      // no frame at all: the watchdog expires
  FaultSchedule encoder_glitches;   // a missed encoder edge (twins), a count spike (simulated)
  FaultSchedule encoder_reversals;  // the encoder runs backwards
  FaultSchedule encoder_stuck;      // the count stops while the belt moves
  FaultSchedule laser_off;          // profiles without the laser line
  FaultSchedule photo_eye_bounces;  // the photo eye's edges bounce (twins)
  int recognizer_delay_ms = 0;      // extra time per part: overload
  bool corrupt_model_base = false;  // one seeded byte of the model base flipped when read

  template <class Visitor>
  void visit(Visitor& v) {
    v("seed", seed, "where in each run every fault falls");
    v("frame_gaps", frame_gaps, "camera frames lost (the sequence number jumps)");
    v("camera_stalls", camera_stalls,
      "no frame at all: the hardware twins wait out camera.frame_timeout_us per timeout");
    v("encoder_glitches", encoder_glitches,
      "hardware twins: the encoder's first edge of each profile missed; simulated: the count "
      "jumps by 1000 ticks");
    v("encoder_reversals", encoder_reversals, "the encoder counts backwards");
    v("encoder_stuck", encoder_stuck, "the encoder count stops while the belt moves");
    v("laser_off", laser_off, "profiles taken with the laser off");
    v("photo_eye_bounces", photo_eye_bounces,
      "hardware twins: each photo-eye edge in these profiles bounces twice");
    v("recognizer_delay_ms", recognizer_delay_ms, "extra recognizer time per part, ms",
      Range{0, 60000});
    v("corrupt_model_base", corrupt_model_base,
      "flip one seeded byte of the model base as it is read: the cell must refuse it");
  }
};

}  // namespace cosmos
