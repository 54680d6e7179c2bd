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
// A group's pieces (recognize_blob_group) whose rows are final, in the order they started.
BlobRecognition recognize_blob(const std::vector<BuiltPart>& pieces,
                               const PartRecognitionContext& context, std::int64_t part_seq);
// A completed builder: its COSMOS finished, the blob recognized and its stream faults marked
// (mark_stream_fault).
BlobRecognition recognize_blob(PartBuilder& builder, const PartRecognitionContext& context,
                               std::int64_t part_seq);

// A group of completed builders that the tracker linked softly, each to the one before, across
// gaps a part's own shadow can explain (part_tracker.hpp), the first too small to be a part
// alone: a part its shadows cut into pieces (blob_groups.hpp forms the groups). The pieces
// are recognized as one blob, from one view of them all (extract_group_view): a piece is no
// part alone, and recognized alone it floats above the belt and fits nearly nothing, after
// the costliest search of all. What that leaves is taken apart piece by piece, each as the
// blob it came in would be. The poses hold at the last piece's last row; stream faults are
// marked. One builder: recognize_blob.
BlobRecognition recognize_blob_group(const std::vector<PartBuilder*>& pieces,
                                     const PartRecognitionContext& context, std::int64_t part_seq);
// The stamps of a group's pieces (in the order they started) as one built part: its rows run
// from the first piece's first to the last piece's last; it has no pipeline of its own.
BuiltPart group_stamps(const std::vector<BuiltPart>& pieces);

// The ERROR pose of a part the loop dropped, at the centre of its tracked extent.
PartRecognition report_lost_part(const LostPart& lost, const PartRecognitionContext& context,
                                 std::int64_t part_seq);

// The median visible area of the base's views, mm^2 (what a part typically shows).
double typical_view_area_mm2(const ModelBase& base);

}  // namespace cosmos
