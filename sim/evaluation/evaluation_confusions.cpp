#include "sim/evaluation/evaluation_confusions.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <utility>

namespace cosmos {
namespace {

using PairTests = std::map<std::pair<std::string, std::string>, std::vector<int>>;

// Most frequent first; ties by truth, then other, so the order does not depend on the records'.
std::vector<ConfusionCount> sorted_counts(const PairTests& pairs) {
  std::vector<ConfusionCount> counts;
  for (const auto& [key, tests] : pairs) {
    std::vector<int> sorted = tests;
    std::sort(sorted.begin(), sorted.end());
    counts.push_back({key.first, key.second, std::move(sorted)});
  }
  std::stable_sort(counts.begin(), counts.end(),
                   [](const ConfusionCount& a, const ConfusionCount& b) {
                     return a.tests.size() > b.tests.size();
                   });
  return counts;
}

std::string name_of(const std::string& name, int part) {
  return name.empty() ? "part " + std::to_string(part) : name;
}

nlohmann::json counts_json(const std::vector<ConfusionCount>& counts, const char* other_key) {
  nlohmann::json list = nlohmann::json::array();
  for (const ConfusionCount& count : counts)
    list.push_back({{"truth", count.truth}, {other_key, count.other}, {"tests", count.tests}});
  return list;
}

void append_lines(std::string& text, const char* title, const std::vector<ConfusionCount>& counts,
                  const char* arrow) {
  if (counts.empty()) return;
  text += title;
  text += ":\n";
  for (const ConfusionCount& count : counts)
    text +=
        "  " + count.truth + arrow + count.other + ": " + std::to_string(count.tests.size()) + "\n";
}

}  // namespace

std::string reason_kind(const std::string& reason) {
  std::string kind;
  for (std::size_t i = 0; i < reason.size();) {
    if (!std::isdigit(static_cast<unsigned char>(reason[i]))) {
      kind += reason[i++];
      continue;
    }
    while (i < reason.size() && (std::isdigit(static_cast<unsigned char>(reason[i])) ||
                                 (reason[i] == '.' && i + 1 < reason.size() &&
                                  std::isdigit(static_cast<unsigned char>(reason[i + 1])))))
      ++i;
    kind += '#';
  }
  return kind;
}

EvaluationConfusions count_confusions(std::span<const EvaluationRecord> records) {
  PairTests wrong, unknown, rejected;
  int known = 0, wrong_count = 0;
  for (const EvaluationRecord& record : records) {
    const std::string truth = name_of(record.truth_name, record.truth_part);
    const std::string predicted = name_of(record.predicted_name, record.predicted_part);
    if (!record.truth_in_model_base) {
      if (!record.rejected) unknown[{truth, predicted}].push_back(record.test_index);
      continue;
    }
    ++known;
    if (record.rejected) {
      rejected[{truth, reason_kind(record.rejection_reason)}].push_back(record.test_index);
    } else if (record.predicted_part != record.truth_part) {
      ++wrong_count;
      wrong[{truth, predicted}].push_back(record.test_index);
    }
  }
  EvaluationConfusions confusions;
  if (known > 0) confusions.wrong_part_rate = static_cast<double>(wrong_count) / known;
  confusions.wrong_parts = sorted_counts(wrong);
  confusions.unknown_accepted = sorted_counts(unknown);
  confusions.false_rejects = sorted_counts(rejected);
  return confusions;
}

nlohmann::json confusions_json(const EvaluationConfusions& confusions) {
  return {
      {"wrong_part_rate", confusions.wrong_part_rate ? nlohmann::json(*confusions.wrong_part_rate)
                                                     : nlohmann::json(nullptr)},
      {"wrong_parts", counts_json(confusions.wrong_parts, "predicted")},
      {"unknown_accepted", counts_json(confusions.unknown_accepted, "predicted")},
      {"false_rejects", counts_json(confusions.false_rejects, "reason")},
  };
}

std::string confusions_text(const EvaluationConfusions& confusions) {
  std::string text;
  append_lines(text, "wrong parts", confusions.wrong_parts, " -> ");
  append_lines(text, "unknown parts accepted", confusions.unknown_accepted, " -> ");
  append_lines(text, "known parts rejected", confusions.false_rejects, ": ");
  return text;
}

}  // namespace cosmos
