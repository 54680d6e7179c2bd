#include "tests/hil/player_log.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cosmos::hil {
namespace {

void write_plan_line(std::ostream& out, const PlayerPlan& plan) {
  out << "plan " << plan.lead_in_frames << ' ' << plan.conveyor_frames << ' ' << plan.end_sequence
      << ' ' << plan.capture_rate_hz << ' ' << plan.ticks_per_frame << ' ' << plan.cell_duration_s
      << '\n';
}

}  // namespace

void write_player_plan(const std::filesystem::path& file, const PlayerPlan& plan) {
  const std::filesystem::path partial = file.string() + ".partial";
  {
    std::ofstream out(partial);
    write_plan_line(out, plan);
  }
  std::filesystem::rename(partial, file);  // readers never see half a plan
}

void write_player_log(const std::filesystem::path& file, const PlayerLog& log) {
  const std::filesystem::path partial = file.string() + ".partial";
  {
    std::ofstream out(partial);
    out.precision(12);
    write_plan_line(out, log.plan);
    for (const PlayedCapture& capture : log.captures) {
      out << "capture " << capture.sequence << ' ' << capture.t_ns << ' ' << capture.content << ' '
          << (capture.stale ? 1 : 0) << ' ' << capture.belt_tick << '\n';
    }
    for (const std::int64_t sequence : log.merged) out << "merged " << sequence << '\n';
    for (const PlayedFault& fault : log.faults) {
      out << "fault " << fault.kind << ' ' << fault.sequence << ' ' << fault.amount << ' '
          << fault.observed << '\n';
    }
    for (const auto& [name, value] : log.counts) out << "count " << name << ' ' << value << '\n';
  }
  std::filesystem::rename(partial, file);
}

PlayerLog read_player_log(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open the player's log");
  PlayerLog log;
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    std::istringstream line(text);
    std::string kind;
    line >> kind;
    bool ok = true;
    if (kind == "plan") {
      PlayerPlan& plan = log.plan;
      ok = static_cast<bool>(line >> plan.lead_in_frames >> plan.conveyor_frames >>
                             plan.end_sequence >> plan.capture_rate_hz >> plan.ticks_per_frame >>
                             plan.cell_duration_s);
    } else if (kind == "capture") {
      PlayedCapture capture;
      int stale = 0;
      ok = static_cast<bool>(line >> capture.sequence >> capture.t_ns >> capture.content >> stale >>
                             capture.belt_tick);
      capture.stale = stale != 0;
      log.captures.push_back(capture);
    } else if (kind == "merged") {
      std::int64_t sequence = 0;
      ok = static_cast<bool>(line >> sequence);
      log.merged.push_back(sequence);
    } else if (kind == "fault") {
      PlayedFault fault;
      ok =
          static_cast<bool>(line >> fault.kind >> fault.sequence >> fault.amount >> fault.observed);
      log.faults.push_back(fault);
    } else if (kind == "count") {
      std::string name;
      std::int64_t value = 0;
      ok = static_cast<bool>(line >> name >> value);
      log.counts[name] = value;
    } else if (!kind.empty()) {
      ok = false;
    }
    if (!ok) {
      throw std::runtime_error(file.string() + ":" + std::to_string(number) +
                               ": not a player record: " + text);
    }
  }
  return log;
}

}  // namespace cosmos::hil
