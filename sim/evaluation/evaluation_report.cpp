#include "sim/evaluation/evaluation_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "core/input_error.hpp"
#include "sim/evaluation/plot_frame.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

using namespace plot;  // the drawing kit of the report's pictures

std::string format_or_dash(const std::optional<double>& value, const char* pattern) {
  return value ? plot::format(pattern, *value) : std::string("&ndash;");
}

void write_png(const fs::path& path, const cv::Mat& image) {
  bool written = false;
  try {
    written = cv::imwrite(path.string(), image);
  } catch (const cv::Exception&) {
    written = false;
  }
  if (!written) throw InputError("cannot write " + path.string());
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) throw InputError("cannot write " + path.string());
}

std::string part_label(int part, const std::string& record_name,
                       std::span<const std::string> part_names) {
  if (part >= 0 && part < static_cast<int>(part_names.size()))
    return part_names[static_cast<std::size_t>(part)];
  return record_name.empty() ? "part " + std::to_string(part) : record_name;
}

cv::Mat confusion_matrix_image(std::span<const EvaluationRecord> records,
                               std::span<const std::string> part_names) {
  // Rows: base parts, then unknown parts; columns: every part seen or predicted, "rejected".
  std::set<int> known_rows, unknown_rows, column_parts;
  std::map<int, std::string> labels;
  for (const EvaluationRecord& record : records) {
    (record.truth_in_model_base ? known_rows : unknown_rows).insert(record.truth_part);
    labels.emplace(record.truth_part, part_label(record.truth_part, record.truth_name, part_names));
    if (record.truth_in_model_base) column_parts.insert(record.truth_part);
    if (!record.rejected) {
      column_parts.insert(record.predicted_part);
      labels.emplace(record.predicted_part,
                     part_label(record.predicted_part, record.predicted_name, part_names));
    }
  }
  std::vector<int> rows(known_rows.begin(), known_rows.end());
  rows.insert(rows.end(), unknown_rows.begin(), unknown_rows.end());
  std::vector<std::string> row_labels, column_labels;
  for (std::size_t r = 0; r < rows.size(); ++r)
    row_labels.push_back(labels[rows[r]] + (r < known_rows.size() ? "" : " (unknown)"));
  const std::vector<int> columns(column_parts.begin(), column_parts.end());
  for (int part : columns) column_labels.push_back(labels[part]);
  column_labels.push_back("rejected");

  std::vector<std::vector<int>> counts(rows.size(), std::vector<int>(column_labels.size(), 0));
  for (const EvaluationRecord& record : records) {
    const auto row = std::find(rows.begin(), rows.end(), record.truth_part) - rows.begin();
    const auto column =
        record.rejected
            ? static_cast<std::ptrdiff_t>(columns.size())
            : std::find(columns.begin(), columns.end(), record.predicted_part) - columns.begin();
    ++counts[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)];
  }
  int most = 1;
  for (const auto& row : counts) most = std::max(most, *std::max_element(row.begin(), row.end()));

  const std::string corner = "true \\ predicted";
  int left_px = text_size(corner).width, top_px = 0;
  for (const auto& label : row_labels) left_px = std::max(left_px, text_size(label).width);
  for (const auto& label : column_labels) top_px = std::max(top_px, text_size(label).width);
  left_px += 20;
  top_px += 20;
  const int width_px = left_px + kCellPx * static_cast<int>(column_labels.size()) + 10;
  const int height_px = top_px + kCellPx * static_cast<int>(rows.size()) + 10;
  cv::Mat image(height_px, width_px, CV_8UC3, kWhite);
  put_text(image, corner, {8, top_px - 8});
  for (std::size_t c = 0; c < column_labels.size(); ++c)
    put_vertical_text(image, column_labels[c],
                      left_px + kCellPx * static_cast<int>(c) + kCellPx / 2, top_px - 6);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const int y = top_px + kCellPx * static_cast<int>(r);
    put_text(image, row_labels[r], {8, y + kCellPx / 2 + 5});
    for (std::size_t c = 0; c < column_labels.size(); ++c) {
      const double shade = static_cast<double>(counts[r][c]) / most;
      const cv::Rect cell(left_px + kCellPx * static_cast<int>(c), y, kCellPx, kCellPx);
      cv::rectangle(image, cell, kWhite * (1 - shade) + kCellDark * shade, cv::FILLED);
      cv::rectangle(image, cell, kGridGray);
      const std::string count = std::to_string(counts[r][c]);
      put_text(image, count,
               {cell.x + (kCellPx - text_size(count).width) / 2, cell.y + kCellPx / 2 + 5},
               shade > 0.5 ? kWhite : kBlack);
    }
  }
  // A rule between base parts and unknown parts: their correct answers differ.
  if (!known_rows.empty() && !unknown_rows.empty()) {
    const int y = top_px + kCellPx * static_cast<int>(known_rows.size());
    cv::line(image, {4, y}, {width_px - 4, y}, kBlack, 2);
  }
  return image;
}

cv::Mat cluster_rate_image(const std::vector<double>& curve) {
  const double clusters =
      std::max<double>(kClusterHitRanks.back(), static_cast<double>(curve.size()));
  PlotFrame frame = draw_frame("Correct part within the top k spectral clusters (Fig. 4.8)",
                               "clusters examined k", "correct-part rate", 1, clusters, 0, 1);
  if (curve.empty()) put_text(frame.image, "no base-part tests", frame.to_px(0.4 * clusters, 0.5));
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const cv::Point point = frame.to_px(static_cast<double>(i + 1), curve[i]);
    if (i > 0)
      cv::line(frame.image, frame.to_px(static_cast<double>(i), curve[i - 1]), point, kPlotBlue, 2,
               cv::LINE_AA);
    cv::circle(frame.image, point, 3, kPlotBlue, cv::FILLED, cv::LINE_AA);
  }
  return frame.image;
}

// A staircase: F(x) = fraction of errors <= x, for the sorted errors.
cv::Mat rotation_cdf_image(const std::vector<double>& sorted_errors_deg) {
  const double largest_deg = sorted_errors_deg.empty() ? 0 : sorted_errors_deg.back();
  const double x_end = nice_ceiling(std::max(1.0, largest_deg));
  PlotFrame frame = draw_frame("Rotation error CDF (correct, asymmetric parts)",
                               "rotation error (degrees)", "fraction of tests", 0, x_end, 0, 1);
  if (sorted_errors_deg.empty())
    put_text(frame.image, "no correct asymmetric tests", frame.to_px(0.1 * x_end, 0.5));
  const double count = static_cast<double>(sorted_errors_deg.size());
  cv::Point previous = frame.to_px(0, 0);
  for (std::size_t i = 0; i < sorted_errors_deg.size(); ++i) {
    const cv::Point riser = frame.to_px(sorted_errors_deg[i], static_cast<double>(i) / count);
    const cv::Point top = frame.to_px(sorted_errors_deg[i], static_cast<double>(i + 1) / count);
    cv::line(frame.image, previous, riser, kPlotBlue, 2, cv::LINE_AA);
    cv::line(frame.image, riser, top, kPlotBlue, 2, cv::LINE_AA);
    previous = top;
  }
  if (!sorted_errors_deg.empty())
    cv::line(frame.image, previous, frame.to_px(x_end, 1), kPlotBlue, 2, cv::LINE_AA);
  return frame.image;
}

std::string html_escape(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

// Metrics rows from the JSON itself, so the page can never disagree with metrics.json. Keys
// come sorted as strings; all-number keys (clusters examined) are put in numeric order.
void metric_rows(std::ostringstream& html, const nlohmann::json& json, const std::string& prefix) {
  std::vector<std::string> keys;
  for (const auto& item : json.items()) keys.push_back(item.key());
  if (std::all_of(keys.begin(), keys.end(), [](const std::string& key) {
        return !key.empty() && key.find_first_not_of("0123456789") == std::string::npos;
      }))
    std::sort(keys.begin(), keys.end(), [](const std::string& a, const std::string& b) {
      return std::stoi(a) < std::stoi(b);
    });
  for (const std::string& key : keys) {
    const nlohmann::json& value = json[key];
    if (value.is_object()) {
      metric_rows(html, value, prefix + key + ".");
      continue;
    }
    const std::string shown = value.is_null()             ? "&ndash;"
                              : value.is_number_integer() ? value.dump()
                                                          : format("%.4g", value.get<double>());
    html << "<tr><td>" << prefix << key << "</td><td>" << shown << "</td></tr>\n";
  }
}

std::string report_html(std::span<const EvaluationRecord> records, const EvaluationMetrics& metrics,
                        std::span<const std::string> part_names) {
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>COSMOS evaluation</title>\n"
          "<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse;"
          "margin-bottom:2em}td,th{border:1px solid #ccc;padding:2px 8px;text-align:left}"
          "img{margin:0 1em 1em 0;vertical-align:top}</style></head><body>\n"
          "<h1>COSMOS evaluation</h1>\n<h2>Metrics</h2>\n<table>\n";
  metric_rows(html, metrics_json(metrics), "");
  html << "</table>\n<h2>Plots</h2>\n"
          "<img src=\"confusion_matrix.png\" alt=\"confusion matrix\">\n"
          "<img src=\"cluster_rate.png\" alt=\"correct-part rate vs clusters examined\">\n"
          "<img src=\"rotation_error_cdf.png\" alt=\"rotation error CDF\">\n"
          "<h2>Parts</h2>\n<table>\n<tr><th>catalog index</th><th>name</th><th>tests</th></tr>\n";
  for (std::size_t part = 0; part < part_names.size(); ++part)
    html << "<tr><td>" << part << "</td><td>" << html_escape(part_names[part]) << "</td><td>"
         << std::count_if(
                records.begin(), records.end(),
                [&](const EvaluationRecord& r) { return r.truth_part == static_cast<int>(part); })
         << "</td></tr>\n";
  html << "</table>\n<h2>Tests</h2>\n<table>\n<tr><th>#</th><th>truth</th><th>predicted</th>"
          "<th>status</th><th>rotation error (deg)</th><th>translation error (mm)</th>"
          "<th>ADD-S / diameter</th><th>time (ms)</th><th>features (ms)</th><th>matching (ms)</th>"
          "<th>registration (ms)</th><th>pose search</th><th>catalog "
          "search</th><th>resting search</th><th>thin scene</th><th>score</th><th>runner-up "
          "(score)</th>"
          "<th>rejected because</th></tr>\n";
  for (std::size_t i = 0; i < records.size(); ++i) {
    const EvaluationRecord& record = records[i];
    const RecordOutcome& outcome = metrics.outcomes[i];
    const bool symmetric_correct =
        outcome.status == RecordStatus::kCorrect && record.truth_symmetric;
    html << "<tr><td>" << record.test_index << "</td><td>"
         << html_escape(part_label(record.truth_part, record.truth_name, part_names)) << "</td><td>"
         << (record.rejected ? std::string("(rejected)")
                             : html_escape(part_label(record.predicted_part, record.predicted_name,
                                                      part_names)))
         << "</td><td>" << record_status_name(outcome.status) << "</td><td>"
         << (symmetric_correct ? "symmetric" : format_or_dash(outcome.rotation_error_deg, "%.3f"))
         << "</td><td>" << format_or_dash(outcome.translation_error_mm, "%.3f") << "</td><td>"
         << format_or_dash(outcome.add_s_over_diameter, "%.4f") << "</td><td>"
         << format("%.2f", record.recognition_ms) << "</td><td>"
         << format("%.2f", record.features_ms) << "</td><td>" << format("%.2f", record.matching_ms)
         << "</td><td>" << format("%.2f", record.registration_ms) << "</td><td>"
         << (record.pose_searched ? "yes" : "no") << "</td><td>"
         << (record.catalog_searched ? "yes" : "no") << "</td><td>"
         << (record.resting_searched ? "yes" : "no") << "</td><td>"
         << (record.thin_scene ? "yes" : "no") << "</td><td>" << format("%.3f", record.score)
         << format(", %.2f seen", record.seen_fraction) << "</td><td>"
         << (record.runner_up_name.empty()
                 ? std::string("&ndash;")
                 : html_escape(record.runner_up_name) + format(" (%.3f", record.runner_up_score) +
                       format(", %.2f seen)", record.runner_up_seen_fraction) +
                       (record.ambiguity_examined
                            ? format("; %.2f of scene and surfaces tell them apart, ",
                                     record.discriminating_fraction) +
                                  format("%.2f of it is the winner's", record.discriminating_share)
                            : std::string()))
         << "</td><td>" << html_escape(record.rejection_reason) << "</td></tr>\n";
  }
  html << "</table>\n</body></html>\n";
  return html.str();
}

}  // namespace

nlohmann::json tests_json(std::span<const EvaluationRecord> records,
                          const EvaluationMetrics& metrics) {
  if (metrics.outcomes.size() != records.size())
    throw std::invalid_argument("evaluation metrics are not those of the records given");
  nlohmann::json tests = nlohmann::json::array();
  for (std::size_t i = 0; i < records.size(); ++i) {
    const EvaluationRecord& record = records[i];
    const RecordOutcome& outcome = metrics.outcomes[i];
    tests.push_back({
        {"test", record.test_index},
        {"truth", record.truth_name},
        {"truth_in_model_base", record.truth_in_model_base},
        {"predicted", record.rejected ? nlohmann::json() : nlohmann::json(record.predicted_name)},
        {"status", record_status_name(outcome.status)},
        {"reason", record.rejection_reason},
        {"recognition_ms", record.recognition_ms},
        {"features_ms", record.features_ms},
        {"matching_ms", record.matching_ms},
        {"registration_ms", record.registration_ms},
        {"pose_searched", record.pose_searched},
        {"catalog_searched", record.catalog_searched},
        {"quick_fit_rank", record.quick_fits_ranked && record.true_part_quick_fit_rank >= 0
                               ? nlohmann::json(record.true_part_quick_fit_rank)
                               : nlohmann::json()},
        {"parts_left_out_by_size", record.parts_left_out_by_size},
        {"parts_left_out_by_signature", record.parts_left_out_by_signature},
        {"confusable_parts_searched", record.confusable_parts_searched},
        {"resting_searched", record.resting_searched},
        {"thin_scene", record.thin_scene},
        {"truth_has_size_variants", record.truth_has_size_variants},
        {"taken_for_size_variant", record.taken_for_size_variant},
        {"add_s_over_diameter", outcome.add_s_over_diameter
                                    ? nlohmann::json(*outcome.add_s_over_diameter)
                                    : nlohmann::json()},
    });
  }
  return tests;
}

void write_evaluation_report(const fs::path& out_dir, std::span<const EvaluationRecord> records,
                             const EvaluationMetrics& metrics,
                             std::span<const std::string> part_names) {
  if (metrics.outcomes.size() != records.size())
    throw std::invalid_argument("evaluation metrics are not those of the records given");
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error || !fs::is_directory(out_dir))
    throw InputError("cannot create report directory " + out_dir.string() +
                     (error ? ": " + error.message() : ""));
  write_text(out_dir / "metrics.json", metrics_json(metrics).dump(2) + "\n");
  write_png(out_dir / "confusion_matrix.png", confusion_matrix_image(records, part_names));
  write_png(out_dir / "cluster_rate.png", cluster_rate_image(metrics.cluster_hit_rate_curve));
  write_png(out_dir / "rotation_error_cdf.png", rotation_cdf_image(metrics.rotation_errors_deg));
  write_text(out_dir / "report.html", report_html(records, metrics, part_names));
  write_text(out_dir / "tests.json", tests_json(records, metrics).dump(1) + "\n");
}

}  // namespace cosmos
