#pragma once
// Every part a completed blob holds, each with a pose or a rejection: no part passes the
// scanner unreported. The tracker closes blobs, not parts: parts touching on the belt (end to
// end or side by side), or closer than the tracker can tell apart (part_tracker.hpp), come as
// one blob. Scene-level recognition takes them apart: recognize the best-explained part in
// the blob, take away the surface it explains (its patches, §5.3, and what it occludes of
// its neighbours, §7.2.5: explained_surface.hpp), recognize what remains, until what lies
// outside the recognized parts' footprints is too small to be another part, or is not
// recognized: then it is taken apart at its necks, or reported as REJECTED, "unresolved
// cluster of N parts", N estimated from its area.
//
// A blob longer than max_part_length_mm lost its end: its unscanned rest is one ERROR pose.
// Parts the loop could not hand over at all (no builder, no queue slot) become ERROR poses
// too, from what the tracker knew of them (report_lost_part).
#include <cstdint>
#include <vector>

#include "realtime/cell/part_recognition.hpp"
#include "realtime/cell/piece_explained.hpp"

namespace cosmos {

struct BlobRecognition {
  std::vector<PartRecognition> parts;  // one per part, in part_seq order
  bool merged = false;                 // it held more than one part
  // The rejections of surface left unexplained (parts[first], count of them: a cluster's
  // estimate), with that surface in the loop frame (every other pixel each way). Left over
  // beside a part recognized in the blob, it may be a piece of a part recognized in another
  // blob (side by side, the tracker can split a part between two): piece_joiner.hpp.
  struct Remnant {
    std::size_t first = 0;
    int count = 1;
    std::vector<Eigen::Vector3d> points_loop_mm;
  };
  std::vector<Remnant> remnants;
  // Its surface in the loop frame (every other pixel each way), to tell later whether a
  // part recognized nearby explains it (piece_joiner.hpp).
  std::vector<Eigen::Vector3d> points_loop_mm;
  RangeImage image;  // its own pixels in the loop frame (the view recognized first)
};

// part_seq: the first part's running number; the blob's parts take the next ones. The
// built part's rows must be final (extract_part_view); stream faults are not marked.
BlobRecognition recognize_blob(const BuiltPart& built, const PartRecognitionContext& context,
                               std::int64_t part_seq);
// A completed builder: its COSMOS finished, the blob recognized and its stream faults marked
// (mark_stream_fault).
BlobRecognition recognize_blob(PartBuilder& builder, const PartRecognitionContext& context,
                               std::int64_t part_seq);

// A leading piece: a completed builder whose successor, a blob the tracker linked to it
// softly across a gap its shadow can explain, is recognized already. When one of the
// successor's parts explains most of the piece and the piece is the smaller of the two (the
// joiner would then drop the piece whatever it was recognized as, piece_joiner.hpp), it is
// not recognized: it comes out as a rejection the joiner drops. A shadow-cut feature in
// front of a part (an elephant's trunk tip) is too small to be recognized and floats above the
// belt, and its failed recognition was the costliest of a cell's. Otherwise: recognize_blob.
BlobRecognition recognize_blob_unless_explained(PartBuilder& builder,
                                                const PartRecognitionContext& context,
                                                const std::vector<PartInLoop>& successor_parts,
                                                std::size_t successor_points,
                                                std::int64_t part_seq);

// The ERROR pose of a part the loop dropped, at the centre of its tracked extent.
PartRecognition report_lost_part(const LostPart& lost, const PartRecognitionContext& context,
                                 std::int64_t part_seq);

// The median visible area of the base's views, mm^2 (what a part typically shows).
double typical_view_area_mm2(const ModelBase& base);

}  // namespace cosmos
