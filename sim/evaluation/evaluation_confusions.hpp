#pragma once
// The outcomes of `cosmos eval` that a work cell pays for, by pair of parts: a known part
// taken for another (the robot picks the wrong thing: the worst outcome), an unknown part
// taken for a base part, and known parts rejected, by reason (a rejection only sends the part
// to the manual bin). Pure: no files, no clock.
//
// JSON (confusions.json beside metrics.json):
//   wrong_part_rate      |known, taken for another part| / |known| (null without known tests).
//   wrong_parts          [{truth, predicted, tests: [test numbers]}], most frequent first.
//   unknown_accepted     the same for unknown parts taken for base parts.
//   false_rejects        [{truth, reason, tests}]: the reason with its numbers taken out, so
//                        "explains only 55 %" and "only 48 %" are counted together.
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sim/evaluation/evaluation_metrics.hpp"

namespace cosmos {

struct ConfusionCount {
  std::string truth;
  std::string other;       // the predicted part, or the rejection's reason
  std::vector<int> tests;  // test numbers, ascending
};

struct EvaluationConfusions {
  std::optional<double> wrong_part_rate;
  std::vector<ConfusionCount> wrong_parts, unknown_accepted, false_rejects;
};

EvaluationConfusions count_confusions(std::span<const EvaluationRecord> records);

nlohmann::json confusions_json(const EvaluationConfusions& confusions);

// One line per entry, "truth -> other: count", for the console.
std::string confusions_text(const EvaluationConfusions& confusions);

// The reason with every run of digits (and a decimal point inside one) replaced by '#'.
std::string reason_kind(const std::string& reason);

}  // namespace cosmos
