#include "realtime/cell/blob_recognition.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "core/recognition/explained_surface.hpp"
#include "realtime/cell/blob_regions.hpp"
#include "realtime/cell/piece_explained.hpp"

namespace cosmos {
namespace {

RigidTransform T_belt_loop() {
  return {Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix(), Eigen::Vector3d::Zero()};
}

// Rows of `explained` that hold a pixel, as the recognition's profile range.
void set_profiles_of(const std::vector<std::uint8_t>& explained, int width, const BuiltPart& built,
                     PartRecognition& recognition) {
  int first = -1, last = -1;
  for (std::size_t i = 0; i < explained.size(); ++i) {
    if (!explained[i]) continue;
    const int row = static_cast<int>(i / static_cast<std::size_t>(width));
    if (first < 0) first = row;
    last = row;
  }
  if (first < 0) return;
  recognition.first_profile = built.first_profile + first;
  recognition.last_profile = built.first_profile + last;
}

// A rejection at the centroid of what remains of the blob.
void place_rejection(const Remaining& remaining, const BuiltPart& built,
                     const PartRecognitionContext& context, PartRecognition& recognition) {
  const RigidTransform T_loop_part{Eigen::Matrix3d::Identity(), remaining.centroid_mm};
  recognition.T_belt_part = T_belt_loop() * T_loop_part;
  const RigidTransform T_cell_part = cell_pose_of(T_loop_part, built, context);
  recognition.pose.rotation_cell_part = Eigen::Quaterniond(T_cell_part.rotation);
  recognition.pose.translation_cell_part_mm = T_cell_part.translation_mm;
  recognition.first_profile = built.first_profile + remaining.first_row;
  recognition.last_profile = built.first_profile + remaining.last_row;
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

namespace {

// A group's pieces in the order they started (the view's rows, first to last).
std::vector<BuiltPart> in_start_order(std::vector<BuiltPart> pieces) {
  std::stable_sort(pieces.begin(), pieces.end(), [](const BuiltPart& a, const BuiltPart& b) {
    return a.first_profile < b.first_profile;
  });
  return pieces;
}

// A recognition that failed on what remained of a region of the blob, with what remained.
struct Unrecognized {
  PartRecognition recognition;
  Remaining remaining;
  RangeImage image;  // what remained, its pixels only
};

// The scene loop over one blob: parts recognized and their surface taken away until what
// remains is explained, too small or not recognized; what is not recognized is taken apart at
// its necks, or reported.
class SceneRecognition {
 public:
  // `pieces`: the blob's builders' parts, one or a group's (recognize_blob_group).
  SceneRecognition(std::vector<BuiltPart> pieces, const PartRecognitionContext& context,
                   std::int64_t part_seq)
      : pieces_(in_start_order(std::move(pieces))),
        built_(group_stamps(pieces_)),
        context_(context),
        parameters_(context.blob),
        part_seq_(part_seq),
        start_(std::chrono::steady_clock::now()) {
    whole_ = extract_group_view(pieces_, context);
    const PartView& view = *whole_;
    width_ = view.image.width();
    height_ = view.image.height();
    const double typical_area_mm2 = typical_view_area_mm2(*context.model_base);
    min_stretch_mm2_ = parameters_.min_stretch_fraction * typical_area_mm2;
    min_unexplained_mm2_ = parameters_.min_unexplained_fraction * typical_area_mm2;
    blob_.points_loop_mm = sampled_points(view.image);
    blob_.image = view.image;
    explained_.assign(pixel_count(), 0);
  }

  BlobRecognition run() {
    std::optional<Unrecognized> rest = recognize_region(nothing_outside(), 0, std::move(whole_));
    if (rest && !take_apart(*rest)) report(*rest, any_recognized());
    if (built_.truncated && built_.tracked_rows > built_.rows) report_unscanned_rest();
    blob_.merged = blob_.parts.size() > 1;
    return std::move(blob_);
  }

 private:
  struct Footprint {
    const PartDistanceField* field;
    RigidTransform T_loop_part;
    double reach_mm;
  };

  std::size_t pixel_count() const { return static_cast<std::size_t>(width_) * height_; }
  std::vector<std::uint8_t> nothing_outside() const {
    return std::vector<std::uint8_t>(pixel_count(), 0);
  }
  bool any_recognized() const {
    return std::any_of(blob_.parts.begin(), blob_.parts.end(), [](const PartRecognition& part) {
      return part.pose.status == PoseStatus::kOk;
    });
  }
  std::int64_t next_seq() const {
    return part_seq_ + static_cast<std::int64_t>(blob_.parts.size());
  }

  // The interior area of what remains outside the footprints of the parts recognized so far.
  double unexplained_mm2(const RangeImage& image, const Remaining& remaining) const {
    std::vector<std::uint8_t> outside = remaining.mask;
    for (const Footprint& footprint : footprints_) {
      const std::vector<std::uint8_t> under =
          footprint_pixels(image, outside, *footprint.field, footprint.T_loop_part,
                           footprint.reach_mm, parameters_.explained_distance_mm);
      for (std::size_t i = 0; i < outside.size(); ++i) outside[i] &= under[i] ? 0 : 1;
    }
    return static_cast<double>(interior_pixels(outside, image.width(), image.height())) *
           image.pixel_size_x_mm * image.pixel_size_y_mm;
  }

  // The loop over one region (pixels of `excluded` left out from the start, and whatever the
  // parts recognized so far explain). Nothing is done when what the region holds outside
  // their footprints is under min_start_mm2. Returns the failed recognition that ended it,
  // if one did, unreported. `prepared`: the region's view, already extracted (the whole blob's,
  // whose analysis is the costliest step of all: it is not done twice).
  std::optional<Unrecognized> recognize_region(std::vector<std::uint8_t> excluded,
                                               double min_start_mm2,
                                               std::optional<PartView> prepared = {}) {
    for (std::size_t i = 0; i < excluded.size(); ++i) excluded[i] |= explained_[i];
    PartView view =
        prepared ? std::move(*prepared) : extract_group_view(pieces_, context_, &excluded);
    Remaining remaining = remaining_of(view.image);
    if (min_start_mm2 > 0 && unexplained_mm2(view.image, remaining) < min_start_mm2) return {};
    double features_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
            .count();
    for (;;) {
      PartRecognition recognition =
          recognize_part_view(view, built_, context_, next_seq(), features_ms);
      if (recognition.result.status != RecognitionStatus::kOk)
        return Unrecognized{std::move(recognition), std::move(remaining), std::move(view.image)};
      const auto cut = std::chrono::steady_clock::now();
      const PartSearchModel& model =
          context_.recognizer->part_search_model(recognition.result.part);
      std::vector<std::uint8_t> explained =
          explained_pixels(blob_.image, model.field, recognition.result.T_scanner_part,
                           parameters_.explained_distance_mm);
      add_explained_pieces(recognition.result.part, recognition.result.T_scanner_part, explained);
      set_profiles_of(explained, width_, built_, recognition);
      std::size_t newly_excluded = 0;
      for (std::size_t i = 0; i < excluded.size(); ++i) {
        newly_excluded += explained[i] && !excluded[i] ? 1 : 0;
        excluded[i] |= explained[i];
        explained_[i] |= explained[i];
      }
      footprints_.push_back(
          {&model.field, recognition.result.T_scanner_part,
           context_.model_base->parts[static_cast<std::size_t>(recognition.result.part)]
               .diameter_mm});
      // What is left of a part its explained surface missed can be recognized as that part
      // again: one pose per part, the rest of its surface taken away too.
      const bool seen_again = repeats_a_part(recognition, blob_.parts, *context_.model_base);
      if (!seen_again) blob_.parts.push_back(std::move(recognition));
      if (seen_again && newly_excluded == 0) return {};
      // Whether enough is left is known from the whole blob's image without the excluded
      // pixels (the very pixels the region's view would hold): most single parts leave too
      // little, and their recognition then ends without analysing the rest anew, which costs
      // a segmentation on the part's latency path.
      remaining = remaining_of(blob_.image, &excluded);
      if (unexplained_mm2(blob_.image, remaining) < min_unexplained_mm2_) return {};
      view = extract_group_view(pieces_, context_, &excluded);
      if (static_cast<int>(blob_.parts.size()) >= parameters_.max_parts_per_blob) {
        // What remains is reported, not recognized: the blob has used its recognitions.
        PartRecognition rest = blob_.parts.back();
        rest.result = RecognitionResult{};
        rest.pose.status = PoseStatus::kRejected;
        rest.pose.part_name.clear();
        rest.pose.part_index = rest.pose.view_index = -1;
        rest.pose.score = rest.pose.registration_rms_mm = 0;
        rest.pose.part_seq = next_seq();
        rest.pose.reason =
            "unresolved cluster of " +
            std::to_string(estimated_parts(remaining.interior_mm2, *context_.model_base)) +
            " parts: more than max_parts_per_blob in one blob";
        place_rejection(remaining, built_, context_, rest);
        blob_.remnants.push_back({blob_.parts.size(), 1, sampled_points(view.image)});
        blob_.parts.push_back(std::move(rest));
        return {};
      }
      features_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cut).count();
    }
  }

  // The view rows of a group's piece k: [piece_row(k), piece_row(k + 1)).
  int piece_row(std::size_t k) const {
    return k < pieces_.size()
               ? static_cast<int>(pieces_[k].first_profile - pieces_[0].first_profile)
               : height_;
  }

  // A group's piece too small to be a part alone (min_stretch_mm2_) that the part recognized,
  // so placed, explains (piece_explained.hpp: the joiner's test, most of its surface on the
  // part's) is all the part's: a feature its shadow cut off, which its explained surface only
  // partly covers where the pose or the model is off at the part's far end.
  void add_explained_pieces(int part, const RigidTransform& T_loop_part,
                            std::vector<std::uint8_t>& explained) const {
    if (pieces_.size() < 2) return;
    const RangeImage& image = blob_.image;
    const double pixel_area_mm2 = image.pixel_size_x_mm * image.pixel_size_y_mm;
    const std::vector<PartInLoop> placed{{part, T_loop_part}};
    for (std::size_t k = 0; k < pieces_.size(); ++k) {
      std::vector<Eigen::Vector3d> points_loop_mm;
      std::size_t pixels = 0;
      for (int row = piece_row(k); row < piece_row(k + 1); ++row)
        for (int column = 0; column < width_; ++column) {
          const float z = image.z_mm(column, row);
          if (std::isnan(z)) continue;
          ++pixels;
          if (row % 2 == 0 && column % 2 == 0)
            points_loop_mm.emplace_back(image.x_mm(column), image.y_mm(row), z);
        }
      if (static_cast<double>(pixels) * pixel_area_mm2 >= min_stretch_mm2_ ||
          !piece_explained_by(points_loop_mm, placed, context_))
        continue;
      for (int row = piece_row(k); row < piece_row(k + 1); ++row)
        for (int column = 0; column < width_; ++column)
          if (!std::isnan(image.z_mm(column, row)))
            explained[static_cast<std::size_t>(row) * width_ + column] = 1;
    }
  }

  // A rejection for what was not recognized: one per part it is estimated to hold.
  void report(Unrecognized& unrecognized, bool beside_others) {
    PartRecognition& recognition = unrecognized.recognition;
    const int count = estimated_parts(unrecognized.remaining.interior_mm2, *context_.model_base);
    const std::string why = recognition.pose.reason;
    if (count > 1)
      recognition.pose.reason = "unresolved cluster of " + std::to_string(count) + " parts: " + why;
    else if (beside_others)
      recognition.pose.reason = "merged with a neighbour, not recognized: " + why;
    recognition.pose.part_seq = next_seq();
    place_rejection(unrecognized.remaining, built_, context_, recognition);
    blob_.remnants.push_back({blob_.parts.size(), count, sampled_points(unrecognized.image)});
    blob_.parts.push_back(std::move(recognition));
    for (int k = 1; k < count; ++k) {
      PartRecognition more = blob_.parts.back();
      more.pose.part_seq = next_seq();
      blob_.parts.push_back(std::move(more));
    }
  }

  // Pixels outside rows (or columns) [begin, end).
  std::vector<std::uint8_t> outside_stretch(int begin, int end, bool along_rows) const {
    std::vector<std::uint8_t> outside(pixel_count(), 1);
    for (int row = 0; row < height_; ++row)
      for (int column = 0; column < width_; ++column) {
        const int at = along_rows ? row : column;
        if (at >= begin && at < end) outside[static_cast<std::size_t>(row) * width_ + column] = 0;
      }
    return outside;
  }

  // What the whole blob's recognition left unrecognized. A group's pieces are taken apart
  // where the tracker cut them: each piece as the blob it came in would have been, recognized
  // on its own whatever its size (a small part whose neighbour's shadow linked it to a part
  // that is not recognized is still a part), what it leaves taken apart at its necks or
  // reported. A single blob is taken apart at its necks. False when nothing was tried.
  bool take_apart(const Unrecognized& unrecognized) {
    if (pieces_.size() == 1) return take_apart_at_necks(unrecognized, nothing_outside());
    // Any piece with surface left is tried: the threshold only passes over empty ones.
    constexpr double kAnySurfaceMm2 = 1e-9;
    for (std::size_t k = 0; k < pieces_.size(); ++k) {
      const std::vector<std::uint8_t> outside =
          outside_stretch(piece_row(k), piece_row(k + 1), true);
      std::optional<Unrecognized> failure = recognize_region(outside, kAnySurfaceMm2);
      if (failure && !take_apart_at_necks(*failure, outside)) report(*failure, any_recognized());
    }
    return true;
  }

  // What was not recognized of the region outside `outside`, where it narrows to necks
  // (touching parts meet in a few pixels): each stretch between necks recognized on its own,
  // along the belt first, then across it. Parts recognized in the stretches leave the rest of
  // the region as one region again (a part the cuts split is whole in it), recognized or
  // reported once; none recognized either way, the failures of the last way tried are
  // reported, one per stretch. False when no stretch was big enough to try.
  bool take_apart_at_necks(const Unrecognized& unrecognized,
                           const std::vector<std::uint8_t>& outside) {
    std::vector<Unrecognized> unresolved;
    for (const bool along_rows : {true, false}) {
      const std::vector<int> cuts = necks(pixels_per(unrecognized.image, along_rows));
      if (cuts.empty()) continue;
      const std::size_t parts_before = blob_.parts.size();
      std::vector<Unrecognized> failures;
      int begin = 0;
      for (std::size_t k = 0; k <= cuts.size(); ++k) {
        const int end = k < cuts.size() ? cuts[k] : (along_rows ? height_ : width_);
        std::vector<std::uint8_t> stretch = outside_stretch(begin, end, along_rows);
        for (std::size_t i = 0; i < stretch.size(); ++i) stretch[i] |= outside[i];
        std::optional<Unrecognized> failure = recognize_region(stretch, min_stretch_mm2_);
        if (failure) failures.push_back(std::move(*failure));
        begin = end;
      }
      if (blob_.parts.size() > parts_before) {
        std::optional<Unrecognized> rest = recognize_region(outside, min_unexplained_mm2_);
        if (rest) report(*rest, true);
        return true;
      }
      if (!failures.empty()) unresolved = std::move(failures);
    }
    const bool several = unresolved.size() > 1 || any_recognized();
    for (Unrecognized& failure : unresolved) report(failure, several);
    return !unresolved.empty();
  }

  // The rows beyond the builder's held more of the blob: one ERROR for that rest.
  void report_unscanned_rest() {
    PartRecognition rest = blob_.parts.back();
    rest.result = RecognitionResult{};
    rest.pose.status = PoseStatus::kError;
    rest.pose.part_name.clear();
    rest.pose.part_index = rest.pose.view_index = -1;
    rest.pose.score = rest.pose.registration_rms_mm = 0;
    rest.pose.part_seq = next_seq();
    const double unscanned_mm =
        static_cast<double>(built_.tracked_rows - built_.rows) * context_.grid_mm;
    rest.pose.reason = "blob longer than tracking.max_part_length_mm: its last " +
                       std::to_string(static_cast<long long>(std::lround(unscanned_mm))) +
                       " mm were not scanned";
    // Reported where the unscanned stretch lies on the belt (its middle, on the belt's
    // surface across the blob's middle), not where the last recognized part is.
    Remaining unscanned;
    unscanned.first_row = static_cast<int>(built_.rows);
    unscanned.last_row = static_cast<int>(built_.tracked_rows - 1);
    double x_sum_mm = 0;
    for (const Eigen::Vector3d& point : blob_.points_loop_mm) x_sum_mm += point.x();
    const double middle_row = 0.5 * (unscanned.first_row + unscanned.last_row);
    unscanned.centroid_mm = {
        blob_.points_loop_mm.empty() ? 0.0
                                     : x_sum_mm / static_cast<double>(blob_.points_loop_mm.size()),
        blob_.image.origin_y_mm + middle_row * blob_.image.pixel_size_y_mm, 0.0};
    place_rejection(unscanned, built_, context_, rest);
    blob_.parts.push_back(std::move(rest));
  }

  const std::vector<BuiltPart> pieces_;
  const BuiltPart built_;  // the pieces' stamps as one
  const PartRecognitionContext& context_;
  const BlobRecognitionParameters& parameters_;
  std::int64_t part_seq_;
  std::chrono::steady_clock::time_point start_;
  int width_ = 0, height_ = 0;
  double min_stretch_mm2_ = 0, min_unexplained_mm2_ = 0;
  BlobRecognition blob_;
  std::optional<PartView> whole_;        // the whole blob's view, until its region takes it
  std::vector<std::uint8_t> explained_;  // what the recognized parts explain, blob-wide
  std::vector<Footprint> footprints_;    // the recognized parts'
};

}  // namespace

BlobRecognition recognize_blob(const BuiltPart& built, const PartRecognitionContext& context,
                               std::int64_t part_seq) {
  return recognize_blob(std::vector<BuiltPart>{built}, context, part_seq);
}

BlobRecognition recognize_blob(const std::vector<BuiltPart>& pieces,
                               const PartRecognitionContext& context, std::int64_t part_seq) {
  return SceneRecognition(pieces, context, part_seq).run();
}

BlobRecognition recognize_blob(PartBuilder& builder, const PartRecognitionContext& context,
                               std::int64_t part_seq) {
  return recognize_blob_group({&builder}, context, part_seq);
}

BuiltPart group_stamps(const std::vector<BuiltPart>& pieces) {
  if (pieces.size() == 1) return pieces.front();
  const auto first = std::min_element(
      pieces.begin(), pieces.end(),
      [](const BuiltPart& a, const BuiltPart& b) { return a.first_profile < b.first_profile; });
  const auto last =
      std::max_element(pieces.begin(), pieces.end(), [](const BuiltPart& a, const BuiltPart& b) {
        return a.last_data_profile < b.last_data_profile;
      });
  BuiltPart group = *first;
  group.cosmos = nullptr;
  group.rows = 0;
  for (const BuiltPart& piece : pieces) {
    group.rows = std::max(group.rows,
                          static_cast<int>(piece.first_profile + piece.rows - group.first_profile));
    group.column_min = std::min(group.column_min, piece.column_min);
    group.column_max = std::max(group.column_max, piece.column_max);
    group.max_z_mm = std::max(group.max_z_mm, piece.max_z_mm);
  }
  group.last_data_profile = last->last_data_profile;
  group.last_data_encoder_ticks = last->last_data_encoder_ticks;
  group.last_data_t_us = last->last_data_t_us;
  group.truncated = last->truncated;
  group.tracked_rows = group.rows + (last->tracked_rows - last->rows);
  return group;
}

BlobRecognition recognize_blob_group(const std::vector<PartBuilder*>& pieces,
                                     const PartRecognitionContext& context, std::int64_t part_seq) {
  std::vector<BuiltPart> built;
  for (PartBuilder* piece : pieces) {
    piece->cosmos.finish();
    built.push_back(piece->built());
  }
  BlobRecognition blob = recognize_blob(built, context, part_seq);
  for (PartRecognition& part : blob.parts)
    for (const PartBuilder* piece : pieces) mark_stream_fault(part, *piece, context);
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
