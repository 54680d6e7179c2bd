#include "realtime/cell/piece_joiner.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

#include "realtime/cell/piece_explained.hpp"

namespace cosmos {
namespace {

// A held piece waits this many blobs for the part it may belong to: the blob that continues
// it completes within a few blobs (side-by-side parts complete in between).
constexpr int kBlobsToWait = 3;
constexpr std::size_t kRecentParts = 8;
// Profiles between a piece and the part it may belong to at most: the longest shadow the
// tracker links across (its link_gap_rows), at the default 0.4 mm belt step.
constexpr std::int64_t kReachProfiles = 100;
// How far a recognized part may reach past its blob's last row and still be taken to end in
// it: a verified pose's error and the hull's rounding, well under the shortest shadow a soft
// link spans (more than hard_link_gap_rows of the belt grid).
constexpr double kPastLastRowMm = 1.0;
// A recognition whose residual is within this fraction of the recognizer's max_rms_mm is
// clear of its rejection limit. A piece of the part behind, cut off by its shadow and
// recognized as a smaller part that ends in it, is fitted where no such part is: its residual
// comes near the limit, and only the part behind tells whether it is a duplicate.
constexpr double kClearRmsFraction = 0.5;

}  // namespace

PieceJoiner::PieceJoiner(const PartRecognitionContext& context) : context_(context) {}

bool PieceJoiner::near(const Piece& piece, const Recognized& part) const {
  return piece.first_profile <= part.last_profile + kReachProfiles &&
         part.first_profile <= piece.last_profile + kReachProfiles;
}

bool PieceJoiner::near(const Piece& a, const Piece& b) const {
  return a.first_profile <= b.last_profile + kReachProfiles &&
         b.first_profile <= a.last_profile + kReachProfiles;
}

namespace {

// One range image holding the surfaces of `pieces` (loop frame, same grid).
RangeImage union_image(const std::vector<const RangeImage*>& pieces) {
  const RangeImage& first = *pieces.front();
  const double grid_x = first.pixel_size_x_mm, grid_y = first.pixel_size_y_mm;
  double x0 = first.origin_x_mm, y0 = first.origin_y_mm, x1 = x0, y1 = y0;
  for (const RangeImage* image : pieces) {
    x0 = std::min(x0, image->origin_x_mm);
    y0 = std::min(y0, image->origin_y_mm);
    x1 = std::max(x1, image->x_mm(image->width() - 1));
    y1 = std::max(y1, image->y_mm(image->height() - 1));
  }
  RangeImage out(static_cast<int>(std::lround((x1 - x0) / grid_x)) + 1,
                 static_cast<int>(std::lround((y1 - y0) / grid_y)) + 1, grid_x, grid_y);
  out.origin_x_mm = x0;
  out.origin_y_mm = y0;
  // The belt where a piece's view measured it; between the pieces (the shadow that cut them
  // apart) nothing is known.
  const bool belt_known = std::all_of(pieces.begin(), pieces.end(),
                                      [](const RangeImage* image) { return image->belt_known(); });
  if (belt_known) out.belt_seen = PixelGrid<std::uint8_t>(out.width(), out.height(), 0);
  for (const RangeImage* image : pieces) {
    const int dc = static_cast<int>(std::lround((image->origin_x_mm - x0) / grid_x));
    const int dr = static_cast<int>(std::lround((image->origin_y_mm - y0) / grid_y));
    for (int row = 0; row < image->height(); ++row)
      for (int column = 0; column < image->width(); ++column) {
        if (const float z = image->z_mm(column, row); !std::isnan(z))
          out.z_mm(column + dc, row + dr) = z;
        if (belt_known) out.belt_seen(column + dc, row + dr) |= image->belt_seen(column, row);
      }
  }
  return out;
}

}  // namespace

void PieceJoiner::remember(const Recognized& part) {
  recent_.push_back(part);
  if (recent_.size() > kRecentParts) recent_.pop_front();
}

void PieceJoiner::release(Piece& piece, std::vector<JoinedRecognition>& out) {
  // A part recognized since the piece was held (in a blob held itself for a while) explains it.
  if (!piece.recognized && explained_by_recent(piece)) {
    piece.rejections.clear();
    return;
  }
  for (const Recognized& part : piece.parts) remember(part);
  for (JoinedRecognition& rejection : piece.rejections) out.push_back(std::move(rejection));
  piece.rejections.clear();
}

bool PieceJoiner::recognize_together(const Piece& piece, const PartBuilder& builder,
                                     std::vector<JoinedRecognition>& out) {
  std::vector<const RangeImage*> images{&piece.image};
  for (const Piece& held : held_)
    if (held.shadow && near(held, piece)) images.push_back(&held.image);
  if (images.size() < 2) return false;
  RangeImage joined = union_image(images);
  // Recognized together on the premise that the pieces are one part's, cut apart by its
  // shadow: that part spans them all (part_size_gate.hpp), and pieces of several parts are
  // explained by none.
  RecognitionResult result = context_.recognizer->recognize(joined, SceneParts::kOne);
  if (result.status != RecognitionStatus::kOk) return false;
  PartRecognition together = recognition_of(std::move(result), builder.built(), context_, 0);
  mark_stream_fault(together, builder, context_);
  if (context_.keep_part_image) {
    // The loop frame's y is the profile index times the grid (ScanLoop::begin_part).
    together.image_first_profile =
        static_cast<std::int64_t>(std::lround(joined.origin_y_mm / joined.pixel_size_y_mm));
    together.image = std::move(joined);
  }
  std::int64_t first_profile = piece.first_profile;
  for (auto held = held_.begin(); held != held_.end();) {
    if (held->shadow && near(*held, piece)) {
      first_profile = std::min(first_profile, held->first_profile);
      held = held_.erase(held);
    } else {
      ++held;
    }
  }
  together.first_profile = first_profile;
  recent_.push_back({together.result.part, together.result.T_scanner_part, together.first_profile,
                     together.last_profile});
  out.push_back({std::move(together), builder.completed_ns});
  return true;
}

bool PieceJoiner::reaches_past(const Recognized& part, std::int64_t last_profile) const {
  const std::vector<Eigen::Vector3d>& hull = context_.model_base->parts[part.part].hull_vertices_mm;
  if (hull.empty()) return true;  // a base without hulls: nothing tells where the part ends
  const RigidTransform& T_loop_part = part.T_loop_part;
  double far_y_mm = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& corner : hull)
    far_y_mm = std::max(far_y_mm, T_loop_part.apply(corner).y());
  return far_y_mm > static_cast<double>(last_profile) * context_.grid_mm + kPastLastRowMm;
}

bool PieceJoiner::clearly_recognized(const Recognized& part) const {
  return part.rms_mm <= kClearRmsFraction * context_.recognizer->parameters().max_rms_mm;
}

bool PieceJoiner::explained_by_recent(const Piece& piece) const {
  std::vector<Recognized> near_parts;
  for (const Recognized& part : recent_)
    if (near(piece, part)) near_parts.push_back(part);
  return explained_by(piece.points_loop_mm, near_parts);
}

bool PieceJoiner::explained_by(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Recognized>& parts) const {
  std::vector<PartInLoop> placed;
  placed.reserve(parts.size());
  for (const Recognized& part : parts) placed.push_back({part.part, part.T_loop_part});
  return piece_explained_by(points, placed, context_);
}

std::vector<std::uint8_t> PieceJoiner::hold_remnants(BlobRecognition& blob,
                                                     const PartBuilder& builder) {
  std::vector<std::uint8_t> held_back(blob.parts.size(), 0);
  for (BlobRecognition::Remnant& remnant : blob.remnants) {
    Piece piece;
    piece.points_loop_mm = std::move(remnant.points_loop_mm);
    piece.first_profile = blob.parts[remnant.first].first_profile;
    piece.last_profile = blob.parts[remnant.first].last_profile;
    const bool explained = explained_by_recent(piece);
    for (std::size_t k = remnant.first; k < remnant.first + remnant.count; ++k) {
      held_back[k] = 1;
      if (!explained) piece.rejections.push_back({std::move(blob.parts[k]), builder.completed_ns});
    }
    if (!explained) held_.push_back(std::move(piece));
  }
  return held_back;
}

std::vector<JoinedRecognition> PieceJoiner::add(BlobRecognition blob, const PartBuilder& builder) {
  return add(std::move(blob), builder, builder);
}

std::vector<JoinedRecognition> PieceJoiner::add(BlobRecognition blob, const PartBuilder& first,
                                                const PartBuilder& builder) {
  std::vector<JoinedRecognition> out;
  std::vector<Recognized> parts;
  for (const PartRecognition& part : blob.parts)
    if (part.pose.status == PoseStatus::kOk)
      parts.push_back({part.result.part, part.result.T_scanner_part, part.first_profile,
                       part.last_profile, part.result.registration_rms_mm});
  const bool any_recognized = !parts.empty();
  const bool soft_linked = builder.has_soft_successor || first.soft_link_of >= 0;
  Piece current;
  current.points_loop_mm = std::move(blob.points_loop_mm);
  current.first_profile = first.first_profile;
  current.last_profile = builder.first_profile + builder.rows_added - 1;
  current.recognized = any_recognized;
  current.parts = parts;
  bool drop_current = false;
  // Held pieces: explained by this blob's parts, theirs; recognized too, the smaller of the
  // two is a duplicate; the others wait, or go out.
  for (auto piece = held_.begin(); piece != held_.end();) {
    bool drop = false;
    if (any_recognized && near(*piece, current)) {
      const bool held_explained = explained_by(piece->points_loop_mm, parts);
      const bool current_explained =
          piece->recognized && soft_linked && explained_by(current.points_loop_mm, piece->parts);
      if (piece->recognized && (held_explained || current_explained)) {
        (piece->points_loop_mm.size() < current.points_loop_mm.size() ? drop : drop_current) = true;
      } else {
        drop = held_explained;
      }
    }
    if (drop) {
      piece = held_.erase(piece);
    } else if (++piece->blobs_waited > kBlobsToWait) {
      piece = release_held(piece, out);
    } else {
      ++piece;
    }
  }
  if (drop_current) return out;
  if (soft_linked && any_recognized && !builder.truncated) {
    // A part recognized in an earlier piece explains this one: a duplicate.
    if (explained_by_recent(current)) return out;
    const bool may_continue_behind =
        std::any_of(parts.begin(), parts.end(), [&](const Recognized& part) {
          return reaches_past(part, current.last_profile) || !clearly_recognized(part);
        });
    if (builder.has_soft_successor && may_continue_behind) {
      ++blobs_held_for_successor_;
      const std::vector<std::uint8_t> held_back = hold_remnants(blob, builder);
      for (std::size_t k = 0; k < blob.parts.size(); ++k)
        if (!held_back[k])
          current.rejections.push_back({std::move(blob.parts[k]), builder.completed_ns});
      held_.push_back(std::move(current));
      return out;
    }
  }
  // A blob with nothing recognized in it may be a piece: of a part already recognized, or of
  // one still to come (a feature cut off by its shadows, or by more than a shadow when the
  // tracker kept it apart outright). Softly linked, it may also be a part its shadows cut
  // into pieces none of which is recognizable alone: recognized together with them.
  if (!any_recognized && !blob.parts.empty() && !builder.truncated && !blob.merged) {
    current.shadow = soft_linked;
    if (soft_linked) current.image = std::move(blob.image);
    if (explained_by_recent(current) || (soft_linked && recognize_together(current, builder, out)))
      return out;
    for (PartRecognition& part : blob.parts)
      current.rejections.push_back({std::move(part), builder.completed_ns});
    held_.push_back(std::move(current));
    return out;
  }
  for (const Recognized& part : parts) remember(part);
  const std::vector<std::uint8_t> held_back = any_recognized
                                                  ? hold_remnants(blob, builder)
                                                  : std::vector<std::uint8_t>(blob.parts.size(), 0);
  for (std::size_t k = 0; k < blob.parts.size(); ++k)
    if (!held_back[k]) out.push_back({std::move(blob.parts[k]), builder.completed_ns});
  return out;
}

std::list<PieceJoiner::Piece>::iterator PieceJoiner::release_held(
    std::list<Piece>::iterator piece, std::vector<JoinedRecognition>& out) {
  if (piece->shadow) {
    // Nearby held pieces none of which was recognized, alone or together: one part.
    for (auto other = std::next(piece); other != held_.end();)
      other = other->shadow && near(*piece, *other) ? held_.erase(other) : std::next(other);
  }
  release(*piece, out);
  return held_.erase(piece);
}

std::vector<JoinedRecognition> PieceJoiner::release_settled(std::int64_t unfinished_from_profile) {
  std::vector<JoinedRecognition> out;
  for (auto piece = held_.begin(); piece != held_.end();)
    piece = piece->last_profile + kReachProfiles < unfinished_from_profile
                ? release_held(piece, out)
                : std::next(piece);
  return out;
}

std::vector<JoinedRecognition> PieceJoiner::finish() {
  std::vector<JoinedRecognition> out;
  while (!held_.empty()) release_held(held_.begin(), out);
  return out;
}

}  // namespace cosmos
