#include "realtime/cell/part_recognition.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "core/representation/cosmos_pipeline.hpp"

namespace cosmos {
namespace {

// Columns kept beside the tracked extent: the fit window's reach, so border pixels keep the
// same neighbourhood as in the builder.
constexpr int kColumnMargin = 4;

RigidTransform T_scanner_belt(std::int64_t encoder_ticks, double mm_per_tick) {
  return {Eigen::Matrix3d::Identity(),
          Eigen::Vector3d(0, static_cast<double>(encoder_ticks) * mm_per_tick, 0)};
}

RigidTransform T_belt_loop() {
  return {Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix(), Eigen::Vector3d::Zero()};
}

}  // namespace

int part_view_first_column(const BuiltPart& built) {
  return std::max(0, built.column_min - kColumnMargin);
}

namespace {

// The loop-frame columns [first, last] of a part's view.
std::pair<int, int> view_columns(const BuiltPart& built) {
  return {part_view_first_column(built),
          std::min(built.cosmos->width() - 1, built.column_max + kColumnMargin)};
}

// Copies the pixels the part owns (and `excluded`, over the whole view, does not take away)
// into `part`, whose row 0 is `row0` rows above the part's first and whose column 0 is
// loop-frame column `c0`: range, belt, frames and fields.
void copy_part_pixels(const BuiltPart& built, const std::vector<std::uint8_t>* excluded, int c0,
                      int row0, PartView& part) {
  const IncrementalCosmos& source = *built.cosmos;
  const auto [first_column, last_column] = view_columns(built);
  const int view_width = part.image.width();
  const int width = last_column - first_column + 1;
  const int dx = first_column - c0;
  const int height = built.rows;
  for (int row = 0; row < height; ++row)
    for (int x = 0; x < width; ++x)
      part.image.belt_seen(x + dx, row + row0) = source.belt_seen(first_column + x, row);
  DarbouxFrameField& frames = part.analysis.frames;
  ShapeIndexField& field = part.analysis.field;
  // Which pixels of the part's columns belong to it, a row at a time (with one column of
  // margin on each side, never owned): the copy below reads each label once instead of nine
  // times (this runs between the part's end and its pose). A pixel outside its row's stored
  // columns has no sample, so no part owns it.
  const int mask_width = width + 2;
  std::vector<std::uint8_t> owned(static_cast<std::size_t>(mask_width) * (height + 2), 0);
  const auto owned_at = [&](int x, int row) -> std::uint8_t& {
    return owned[static_cast<std::size_t>(row + 1) * mask_width + (x + 1)];
  };
  for (int row = 0; row < height; ++row) {
    const PartRow in = source.row(row);
    for (int x = 0; x < width; ++x) {
      const int column = first_column + x;
      const std::size_t at = static_cast<std::size_t>(row + row0) * view_width + (x + dx);
      const bool away = excluded && (*excluded)[at] != 0;
      owned_at(x, row) =
          !away && in.holds(column) && built.owns(in.tracker_label[in.at(column)]) ? 1 : 0;
    }
  }
  for (int row = 0; row < height; ++row) {
    const PartRow in = source.row(row);
    const float y_mm = source.y_mm(row);
    for (int x = 0; x < width; ++x) {
      if (!owned_at(x, row)) continue;
      const std::size_t from = in.at(first_column + x);
      const std::size_t to = static_cast<std::size_t>(row + row0) * view_width + (x + dx);
      part.image.z_mm[to] = in.z_mm[from];
      std::uint8_t same_side = in.same_side[from];
      for (int k = 0; k < 8; ++k)
        if (!owned_at(x + kNeighborOffsets[k].column, row + kNeighborOffsets[k].row))
          same_side &= static_cast<std::uint8_t>(~(1u << k));
      frames.valid[to] = in.valid[from];
      frames.same_side[to] = same_side;
      frames.position_mm[0][to] = source.x_mm(first_column + x);
      frames.position_mm[1][to] = y_mm;
      frames.position_mm[2][to] = in.fitted_z_mm[from];
      for (int c = 0; c < kFrameComponents; ++c) frames.frame[c][to] = in.frame[c][from];
      field.label[to] = in.label[from];
      field.shape_index[to] = in.shape_index[from];
      field.curvedness_per_mm[to] = in.curvedness_per_mm[from];
      field.area_mm2[to] = in.area_mm2[from];
      field.same_side[to] = same_side;
    }
  }
}

}  // namespace

PartView extract_part_view(const BuiltPart& built, const PartRecognitionContext& context,
                           const std::vector<std::uint8_t>* excluded) {
  return extract_group_view({built}, context, excluded);
}

PartView extract_group_view(const std::vector<BuiltPart>& pieces,
                            const PartRecognitionContext& context,
                            const std::vector<std::uint8_t>* excluded) {
  const BuiltPart& first = *std::min_element(
      pieces.begin(), pieces.end(),
      [](const BuiltPart& a, const BuiltPart& b) { return a.first_profile < b.first_profile; });
  int c0 = view_columns(first).first, c1 = view_columns(first).second;
  std::int64_t end_profile = first.first_profile;
  for (const BuiltPart& piece : pieces) {
    c0 = std::min(c0, view_columns(piece).first);
    c1 = std::max(c1, view_columns(piece).second);
    end_profile = std::max(end_profile, piece.first_profile + piece.rows);
  }
  const int width = c1 - c0 + 1;
  const int height = static_cast<int>(end_profile - first.first_profile);
  PartView part;
  part.image = RangeImage(width, height, context.grid_mm, context.grid_mm);
  part.image.origin_x_mm = first.cosmos->origin_x_mm() + c0 * context.grid_mm;
  part.image.origin_y_mm = first.cosmos->origin_y_mm();
  // Where the belt was measured, over the pieces' views: a pixel of another part or of a
  // shadow is not belt (surface_seen.hpp), and between the pieces nothing was measured.
  part.image.belt_seen = PixelGrid<std::uint8_t>(width, height, 0);
  part.analysis.frames = DarbouxFrameField(width, height);
  part.analysis.field = make_shape_index_field(width, height);
  for (const BuiltPart& piece : pieces)
    copy_part_pixels(piece, excluded, c0,
                     static_cast<int>(piece.first_profile - first.first_profile), part);
  // One part's own pixels: the seeds its builder found row by row are the view's. Pieces
  // from several builders, or pixels taken away, are searched in the view.
  const RowSeeds& row_seeds = first.cosmos->seeds();
  if (pieces.size() == 1 && !excluded &&
      row_seeds.holds_part([&first](std::int64_t id) { return first.owns(id); })) {
    if (std::optional<ShapeSeeds> seeds = row_seeds.view_seeds(part.analysis.field, c0)) {
      part.seeds_from_rows = true;
      finish_view_analysis(part.analysis, *seeds, context.cosmos);
      return part;
    }
  }
  finish_view_analysis(part.analysis, context.cosmos);
  return part;
}

RigidTransform cell_pose_of_belt(const RigidTransform& T_belt_part, std::int64_t encoder_ticks,
                                 const PartRecognitionContext& context) {
  return (context.T_cell_scanner * T_scanner_belt(encoder_ticks, context.mm_per_tick) * T_belt_part)
      .normalized();
}

RigidTransform cell_pose_of(const RigidTransform& T_loop_part, const BuiltPart& built,
                            const PartRecognitionContext& context) {
  return cell_pose_of_belt(T_belt_loop() * T_loop_part, built.last_data_encoder_ticks, context);
}

PartRecognition recognize_part(const BuiltPart& built, const PartRecognitionContext& context,
                               std::int64_t part_seq) {
  const auto start = std::chrono::steady_clock::now();
  const PartView part = extract_part_view(built, context);
  const double features_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return recognize_part_view(part, built, context, part_seq, features_ms);
}

PartRecognition recognize_part_view(const PartView& part, const BuiltPart& built,
                                    const PartRecognitionContext& context, std::int64_t part_seq,
                                    double features_ms) {
  PartRecognition out =
      recognition_of(context.recognizer->recognize_analyzed(part.image, part.analysis, features_ms,
                                                            SceneParts::kOneOrMore),
                     built, context, part_seq);
  if (context.keep_part_image) {
    out.image = part.image;
    out.image_first_profile = built.first_profile;
  }
  return out;
}

void mark_stream_fault(PartRecognition& recognition, const PartBuilder& builder,
                       const PartRecognitionContext& context) {
  if (!context.stream_faults || recognition.pose.status == PoseStatus::kError) return;
  const StreamFaultKind fault =
      context.stream_faults->fault_in({static_cast<std::uint64_t>(builder.first_profile),
                                       static_cast<std::uint64_t>(builder.last_data_profile),
                                       static_cast<std::uint64_t>(builder.last_profile)});
  if (fault == StreamFaultKind::kNone) return;
  recognition.pose.status = PoseStatus::kError;
  recognition.pose.reason = std::string("the part's rows span a stream fault (") +
                            to_string(fault) + "): rows missing or its encoder count wrong";
}

PartRecognition recognition_of(RecognitionResult result, const BuiltPart& built,
                               const PartRecognitionContext& context, std::int64_t part_seq) {
  PartRecognition out;
  out.result = std::move(result);
  PartPose& pose = out.pose;
  pose.utime_us = built.last_data_t_us;
  pose.part_seq = part_seq;
  pose.encoder_ticks = built.last_data_encoder_ticks;
  pose.encoder_ticks_first = built.first_encoder_ticks;
  pose.blob_extent_mm = Eigen::Vector3d((built.column_max - built.column_min + 1) * context.grid_mm,
                                        built.rows * context.grid_mm, built.max_z_mm);
  if (out.result.status == RecognitionStatus::kOk) {
    pose.status = PoseStatus::kOk;
    const auto base_part = static_cast<std::size_t>(out.result.part);
    pose.part_name = context.model_base->parts[base_part].name;
    pose.part_index = base_part < context.catalog_index_of_base_part.size()
                          ? context.catalog_index_of_base_part[base_part]
                          : out.result.part;
    pose.view_index =
        context.model_base->views[static_cast<std::size_t>(out.result.view)].view_index;
  } else {
    pose.status = PoseStatus::kRejected;
    pose.reason = out.result.reason;
  }
  out.T_belt_part = T_belt_loop() * out.result.T_scanner_part;
  out.first_profile = built.first_profile;
  out.last_profile = built.first_profile + built.rows - 1;
  const RigidTransform T_cell_part =
      cell_pose_of_belt(out.T_belt_part, built.last_data_encoder_ticks, context);
  pose.rotation_cell_part = Eigen::Quaterniond(T_cell_part.rotation);
  pose.translation_cell_part_mm = T_cell_part.translation_mm;
  pose.score = out.result.score;
  pose.registration_rms_mm = out.result.registration_rms_mm;
  return out;
}

RigidTransform belt_pose_of(const PartPose& pose, const RigidTransform& T_cell_scanner,
                            double mm_per_tick) {
  const RigidTransform T_cell_part{pose.rotation_cell_part.toRotationMatrix(),
                                   pose.translation_cell_part_mm};
  return T_scanner_belt(pose.encoder_ticks, mm_per_tick).inverse() * T_cell_scanner.inverse() *
         T_cell_part;
}

}  // namespace cosmos
