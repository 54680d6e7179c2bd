#include "realtime/cell/blob_recognition.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/recognition/explained_surface.hpp"

namespace cosmos {
namespace {

RigidTransform T_belt_loop() {
  return {Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix(), Eigen::Vector3d::Zero()};
}

// The pixels of `view` that still hold data, their centroid (loop frame) and row range.
struct Remaining {
  std::vector<std::uint8_t> mask;
  std::int64_t pixels = 0;
  double interior_mm2 = 0;
  Eigen::Vector3d centroid_mm = Eigen::Vector3d::Zero();
  int first_row = 0;
  int last_row = -1;
};

Remaining remaining_of(const RangeImage& image) {
  Remaining out;
  const int width = image.width();
  const int height = image.height();
  out.mask.assign(static_cast<std::size_t>(width) * height, 0);
  out.first_row = height;
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const float z = image.z_mm(column, row);
      if (std::isnan(z)) continue;
      out.mask[static_cast<std::size_t>(row) * width + column] = 1;
      ++out.pixels;
      out.centroid_mm += Eigen::Vector3d(image.x_mm(column), image.y_mm(row), z);
      out.first_row = std::min(out.first_row, row);
      out.last_row = std::max(out.last_row, row);
    }
  }
  if (out.pixels > 0) out.centroid_mm /= static_cast<double>(out.pixels);
  out.interior_mm2 = static_cast<double>(interior_pixels(out.mask, width, height)) *
                     image.pixel_size_x_mm * image.pixel_size_y_mm;
  return out;
}

// Rows of `explained` that hold a pixel, as the recognition's profile range.
void set_profiles_of(const std::vector<std::uint8_t>& explained, int width,
                     const PartBuilder& builder, PartRecognition& recognition) {
  int first = -1, last = -1;
  for (std::size_t i = 0; i < explained.size(); ++i) {
    if (!explained[i]) continue;
    const int row = static_cast<int>(i / static_cast<std::size_t>(width));
    if (first < 0) first = row;
    last = row;
  }
  if (first < 0) return;
  recognition.first_profile = builder.first_profile + first;
  recognition.last_profile = builder.first_profile + last;
}

// A rejection at the centroid of what remains of the blob.
void place_rejection(const Remaining& remaining, const PartBuilder& builder,
                     const PartRecognitionContext& context, PartRecognition& recognition) {
  const RigidTransform T_loop_part{Eigen::Matrix3d::Identity(), remaining.centroid_mm};
  recognition.T_belt_part = T_belt_loop() * T_loop_part;
  const RigidTransform T_cell_part = cell_pose_of(T_loop_part, builder, context);
  recognition.pose.rotation_cell_part = Eigen::Quaterniond(T_cell_part.rotation);
  recognition.pose.translation_cell_part_mm = T_cell_part.translation_mm;
  recognition.first_profile = builder.first_profile + remaining.first_row;
  recognition.last_profile = builder.first_profile + remaining.last_row;
}

// How many parts an unrecognized region of `area_mm2` holds: what a part shows at most is
// about the upper decile of the views' visible areas.
int estimated_parts(double area_mm2, const ModelBase& base) {
  std::vector<double> areas;
  for (const ModelBaseView& view : base.views) areas.push_back(view.cosmos.visible_area_mm2);
  if (areas.empty()) return 1;
  std::sort(areas.begin(), areas.end());
  const double largest_mm2 = areas[areas.size() * 9 / 10];
  return std::max(1, static_cast<int>(std::ceil(area_mm2 / std::max(largest_mm2, 1.0) - 0.25)));
}

// Where the blob narrows to a neck along one axis (rows: along the belt, parts touching end
// to end; columns: across it, parts side by side): the counts of its pixels per row (or
// column) at most a fifth of the largest, one cut per neck at its narrowest, away from the
// blob's ends.
std::vector<int> necks(const std::vector<int>& count) {
  constexpr double kNeckFraction = 0.2;
  constexpr int kEnd = 40;  // 16 mm at 0.4 mm: a part is longer and wider than that
  const int widest = count.empty() ? 0 : *std::max_element(count.begin(), count.end());
  int first = -1, last = -1;
  for (int k = 0; k < static_cast<int>(count.size()); ++k)
    if (count[static_cast<std::size_t>(k)] > 0) {
      if (first < 0) first = k;
      last = k;
    }
  const auto narrow = [&](int k) {
    return count[static_cast<std::size_t>(k)] <= kNeckFraction * widest;
  };
  std::vector<int> cuts;
  for (int k = first + kEnd; k < last - kEnd; ++k) {
    if (!narrow(k)) continue;
    int narrowest = k;
    for (; k < last - kEnd && narrow(k); ++k)
      if (count[static_cast<std::size_t>(k)] < count[static_cast<std::size_t>(narrowest)])
        narrowest = k;
    if (cuts.empty() || narrowest - cuts.back() >= kEnd) cuts.push_back(narrowest);
  }
  return cuts;
}

std::vector<int> pixels_per(const RangeImage& image, bool rows) {
  std::vector<int> count(static_cast<std::size_t>(rows ? image.height() : image.width()), 0);
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column)
      if (!std::isnan(image.z_mm(column, row)))
        ++count[static_cast<std::size_t>(rows ? row : column)];
  return count;
}

// Whether `recognition` is a part already recognized in the blob, at the same place: the
// same base part within a tenth of its diameter (the identification criterion of ADD-S).
bool repeats_a_part(const PartRecognition& recognition, const std::vector<PartRecognition>& parts,
                    const ModelBase& base) {
  const int part = recognition.result.part;
  const double diameter_mm = base.parts[static_cast<std::size_t>(part)].diameter_mm;
  return std::any_of(parts.begin(), parts.end(), [&](const PartRecognition& earlier) {
    return earlier.result.status == RecognitionStatus::kOk && earlier.result.part == part &&
           (earlier.T_belt_part.translation_mm - recognition.T_belt_part.translation_mm).norm() <
               0.1 * diameter_mm;
  });
}

}  // namespace

double typical_view_area_mm2(const ModelBase& base) {
  std::vector<double> areas;
  for (const ModelBaseView& view : base.views) areas.push_back(view.cosmos.visible_area_mm2);
  if (areas.empty()) return 0;
  std::nth_element(areas.begin(), areas.begin() + static_cast<long>(areas.size() / 2), areas.end());
  return areas[areas.size() / 2];
}

BlobRecognition recognize_blob(PartBuilder& builder, const PartRecognitionContext& context,
                               std::int64_t part_seq) {
  const BlobRecognitionParameters& parameters = context.blob;
  const auto start = std::chrono::steady_clock::now();
  const auto since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
  };
  PartView view = extract_part_view(builder, context);
  const int width = view.image.width();
  const double min_remaining_mm2 =
      parameters.min_remaining_fraction * typical_view_area_mm2(*context.model_base);
  BlobRecognition blob;
  for (int row = 0; row < view.image.height(); row += 2)
    for (int column = 0; column < width; column += 2)
      if (const float z = view.image.z_mm(column, row); !std::isnan(z))
        blob.points_loop_mm.emplace_back(view.image.x_mm(column), view.image.y_mm(row), z);
  blob.image = view.image;
  // The scene loop over one region of the blob (pixels outside it excluded from the start).
  const auto recognize_region = [&](std::vector<std::uint8_t> excluded, bool skip_small) {
    PartView view = extract_part_view(builder, context, &excluded);
    Remaining remaining = remaining_of(view.image);
    if (skip_small && remaining.interior_mm2 < min_remaining_mm2) return;
    double features_ms = since(start);
    for (;;) {
      const std::int64_t seq = part_seq + static_cast<std::int64_t>(blob.parts.size());
      PartRecognition recognition = recognize_part_view(view, builder, context, seq, features_ms);
      if (recognition.result.status != RecognitionStatus::kOk) {
        const int count = estimated_parts(remaining.interior_mm2, *context.model_base);
        const std::string why = recognition.pose.reason;
        if (count > 1)
          recognition.pose.reason =
              "unresolved cluster of " + std::to_string(count) + " parts: " + why;
        else if (!blob.parts.empty())
          recognition.pose.reason = "merged with a neighbour, not recognized: " + why;
        place_rejection(remaining, builder, context, recognition);
        blob.parts.push_back(std::move(recognition));
        for (int k = 1; k < count; ++k) {
          PartRecognition more = blob.parts.back();
          more.pose.part_seq = part_seq + static_cast<std::int64_t>(blob.parts.size());
          blob.parts.push_back(std::move(more));
        }
        break;
      }
      const PartSearchModel& model = context.recognizer->part_search_model(recognition.result.part);
      const std::vector<std::uint8_t> explained =
          explained_pixels(view.image, model.field, recognition.result.T_scanner_part,
                           parameters.explained_distance_mm);
      set_profiles_of(explained, width, builder, recognition);
      std::size_t newly_excluded = 0;
      for (std::size_t i = 0; i < excluded.size(); ++i) {
        newly_excluded += explained[i] && !excluded[i] ? 1 : 0;
        excluded[i] |= explained[i];
      }
      // What is left of a part its explained surface missed can be recognized as that part
      // again: one pose per part, the rest of its surface taken away too.
      const bool seen_again = repeats_a_part(recognition, blob.parts, *context.model_base);
      if (!seen_again) blob.parts.push_back(std::move(recognition));
      if (seen_again && newly_excluded == 0) break;
      const auto cut = std::chrono::steady_clock::now();
      view = extract_part_view(builder, context, &excluded);
      remaining = remaining_of(view.image);
      if (remaining.interior_mm2 < min_remaining_mm2) break;
      if (static_cast<int>(blob.parts.size()) >= parameters.max_parts_per_blob) {
        // What remains is reported, not recognized: the blob has used its recognitions.
        PartRecognition rest = blob.parts.back();
        rest.result = RecognitionResult{};
        rest.pose.status = PoseStatus::kRejected;
        rest.pose.part_name.clear();
        rest.pose.part_index = rest.pose.view_index = -1;
        rest.pose.score = rest.pose.registration_rms_mm = 0;
        rest.pose.part_seq = part_seq + static_cast<std::int64_t>(blob.parts.size());
        rest.pose.reason =
            "unresolved cluster of " +
            std::to_string(estimated_parts(remaining.interior_mm2, *context.model_base)) +
            " parts: more than max_parts_per_blob in one blob";
        place_rejection(remaining, builder, context, rest);
        blob.parts.push_back(std::move(rest));
        break;
      }
      features_ms = since(cut);
    }
  };
  recognize_region(
      std::vector<std::uint8_t>(static_cast<std::size_t>(width) * view.image.height(), 0), false);
  // Nothing recognized in a blob with necks (touching parts meet in a few pixels): each
  // stretch between necks is recognized on its own, along the belt first, then across it.
  const int height = view.image.height();
  const auto none_recognized = [&blob] {
    return std::none_of(blob.parts.begin(), blob.parts.end(), [](const PartRecognition& part) {
      return part.pose.status == PoseStatus::kOk;
    });
  };
  for (const bool along_rows : {true, false}) {
    const std::vector<int> cuts = necks(pixels_per(view.image, along_rows));
    if (cuts.empty() || !none_recognized()) continue;
    blob.parts.clear();
    int begin = 0;
    for (std::size_t k = 0; k <= cuts.size(); ++k) {
      const int end = k < cuts.size() ? cuts[k] : (along_rows ? height : width);
      std::vector<std::uint8_t> outside(static_cast<std::size_t>(width) * height, 1);
      for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column) {
          const int at = along_rows ? row : column;
          if (at >= begin && at < end) outside[static_cast<std::size_t>(row) * width + column] = 0;
        }
      recognize_region(std::move(outside), true);
      begin = end;
    }
  }
  // Stretches all too small to be parts: the blob as a whole is what gets reported.
  if (blob.parts.empty())
    recognize_region(std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height, 0), false);
  if (builder.truncated && builder.tracked_rows > builder.cosmos.rows()) {
    // The rows beyond the builders' held more of the blob: one ERROR for that rest.
    PartRecognition rest = blob.parts.back();
    rest.result = RecognitionResult{};
    rest.pose.status = PoseStatus::kError;
    rest.pose.part_name.clear();
    rest.pose.part_index = rest.pose.view_index = -1;
    rest.pose.score = rest.pose.registration_rms_mm = 0;
    rest.pose.part_seq = part_seq + static_cast<std::int64_t>(blob.parts.size());
    const double unscanned_mm =
        static_cast<double>(builder.tracked_rows - builder.cosmos.rows()) * context.grid_mm;
    rest.pose.reason = "blob longer than tracking.max_part_length_mm: its last " +
                       std::to_string(static_cast<long long>(std::lround(unscanned_mm))) +
                       " mm were not scanned";
    // Reported where the unscanned stretch lies on the belt (its middle, on the belt's
    // surface across the blob's middle), not where the last recognized part is.
    Remaining unscanned;
    unscanned.first_row = static_cast<int>(builder.cosmos.rows());
    unscanned.last_row = static_cast<int>(builder.tracked_rows - 1);
    double x_sum_mm = 0;
    for (const Eigen::Vector3d& point : blob.points_loop_mm) x_sum_mm += point.x();
    const double middle_row = 0.5 * (unscanned.first_row + unscanned.last_row);
    unscanned.centroid_mm = {blob.points_loop_mm.empty()
                                 ? 0.0
                                 : x_sum_mm / static_cast<double>(blob.points_loop_mm.size()),
                             view.image.origin_y_mm + middle_row * view.image.pixel_size_y_mm, 0.0};
    place_rejection(unscanned, builder, context, rest);
    blob.parts.push_back(std::move(rest));
  }
  blob.merged = blob.parts.size() > 1;
  return blob;
}

PartRecognition report_lost_part(const LostPart& lost, const PartRecognitionContext& context,
                                 std::int64_t part_seq) {
  PartRecognition out;
  PartPose& pose = out.pose;
  pose.utime_us = lost.last_t_us;
  pose.part_seq = part_seq;
  pose.encoder_ticks = lost.last_encoder_ticks;
  pose.encoder_ticks_first = lost.first_encoder_ticks;
  pose.status = PoseStatus::kError;
  pose.reason = lost_part_reason_text(lost.reason);
  const double rows = static_cast<double>(lost.last_profile - lost.first_profile + 1);
  pose.blob_extent_mm = Eigen::Vector3d((lost.column_max - lost.column_min + 1) * context.grid_mm,
                                        rows * context.grid_mm, lost.max_z_mm);
  const Eigen::Vector3d centre_loop_mm(
      context.x0_loop_mm + 0.5 * (lost.column_min + lost.column_max) * context.grid_mm,
      0.5 * static_cast<double>(lost.first_profile + lost.last_profile) * context.grid_mm,
      0.5 * lost.max_z_mm);
  out.T_belt_part = T_belt_loop() * RigidTransform{Eigen::Matrix3d::Identity(), centre_loop_mm};
  const RigidTransform T_cell_part =
      cell_pose_of_belt(out.T_belt_part, lost.last_encoder_ticks, context);
  pose.rotation_cell_part = Eigen::Quaterniond(T_cell_part.rotation);
  pose.translation_cell_part_mm = T_cell_part.translation_mm;
  out.first_profile = lost.first_profile;
  out.last_profile = lost.last_profile;
  return out;
}

}  // namespace cosmos
