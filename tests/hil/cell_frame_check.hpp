#pragma once
// The cell check's frame accounting and fault traces (cell_check.hpp's "frames" and
// "faults"), on the context the whole check shares: the run, the cell's profiles by sequence
// number and time stamp, the player's captures, and what the parts check found.
#include <cstdint>
#include <map>
#include <set>
#include <vector>

#include "tests/hil/cell_check.hpp"

namespace cosmos::hil {

struct CellCheckContext {
  explicit CellCheckContext(const CellRun& cell_run)
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

// The median (the upper one of an even count); 0 for none.
double median(std::vector<double> values);

// Every frame vivid filled reached the cell as a profile of its number and time stamp; the
// dropped counts agree with the sequence gaps (and COSMOS_STATUS); sets c.sequence_gaps.
void check_frames(CellCheckContext& c, std::vector<ProbeCheck>& checks);
// Each injected fault's trace in the cell's profiles, and the player's counts.
void check_fault_traces(const CellCheckContext& c, std::vector<ProbeCheck>& checks);

}  // namespace cosmos::hil
