#pragma once
// The recognizer worker's step for one completed part: the part's view cut out of its
// builder (rows of the part, columns of its tracked extent plus a margin, pixels of other
// parts masked out), the rest of the chapter-3 pipeline on the builder's finished fields
// (finish_view_analysis, the very code that ends analyze_view, so the features equal
// whole-image processing of the part's rows; the CSMP seeds the builder found row by row),
// recognition
// (core/recognition/recognizer.hpp), and the pose turned from the loop frame into the cell frame:
//   T_belt_part  = R_belt_loop T_loop_part        (R_belt_loop = Rz(180°), scan_loop.hpp)
//   T_cell_part  = T_cell_scanner T_scanner_belt(e) T_belt_part
// at the encoder count e of the part's last row, where the belt has carried the part by
// e · mm_per_tick along +y (sim/conveyor_scene.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/range_image.hpp"
#include "core/recognition/recognizer.hpp"
#include "core/representation/cosmos_pipeline.hpp"
#include "core/rigid_transform.hpp"
#include "realtime/cell/part_pose.hpp"
#include "realtime/loop/scan_loop.hpp"
#include "realtime/sources/stream_fault_log.hpp"

namespace cosmos {

// How a blob that holds several parts is taken apart (blob_recognition.hpp).
struct BlobRecognitionParameters {
  // A blob pixel this close to a recognized part's surface is that part's, mm: a few times
  // the registration's residual and the distance field's half-voxel error.
  double explained_distance_mm = 3.0;
  // Fractions of the median visible area of the base's views (CosmosView::visible_area_mm2).
  // A stretch of a blob between two necks is recognized on its own when its interior area is
  // at least min_stretch_fraction of it: smaller, it is no part alone.
  double min_stretch_fraction = 0.15;
  // Once parts are recognized in a blob, what they leave is another object when the interior
  // area of it outside their footprints (explained_surface.hpp) is at least
  // min_unexplained_fraction: inside them it is their own unmodelled surface, however large,
  // and outside them even a part the others mostly hide from the camera shows this much.
  double min_unexplained_fraction = 0.05;
  int max_parts_per_blob = 6;  // recognitions per blob at most
};

struct PartRecognitionContext {
  const Recognizer* recognizer = nullptr;
  const ModelBase* model_base = nullptr;
  CosmosParameters cosmos;
  std::vector<int> catalog_index_of_base_part;  // PartPose::part_index per base part
  RigidTransform T_cell_scanner;
  double mm_per_tick = 0.1;
  double grid_mm = 0.4;
  double x0_loop_mm = 0;
  // Hand the part's view image on with its pose (PartRecognition::image), for the live web
  // view's belt strip: the recognizer made it anyway, so keeping it costs a move.
  bool keep_part_image = false;
  // The source's stream faults (stream_checked_source.hpp): a part whose rows span one is
  // published as ERROR. Null: unchecked.
  const StreamFaultLog* stream_faults = nullptr;
  BlobRecognitionParameters blob;
};

// The part's range image and chapter-3 analysis in the loop frame.
struct PartView {
  RangeImage image;
  ViewAnalysis analysis;
  // Its CSMP seeds were those the builder found as the rows arrived (row_seeds.hpp), not
  // searched in the view: the same seeds, found before the part's end.
  bool seeds_from_rows = false;
};
// The part's rows must be final: those of a completed builder once its COSMOS is finished
// (recognize_blob(PartBuilder&) drains the pipeline's last rows on the recognizer's thread:
// the work of many rows at once, far more than one line period allows), or rows the pipeline
// has already passed (a part recognized before the tracker completed it).
// `excluded` (the view's size, row-major; null: none): pixels also masked out, those that
// parts already recognized in the blob explain (blob_recognition.hpp).
PartView extract_part_view(const BuiltPart& built, const PartRecognitionContext& context,
                           const std::vector<std::uint8_t>* excluded = nullptr);
// The view of a group's pieces (builders the tracker linked softly, blob_recognition.hpp) as
// one: each piece's pixels as extract_part_view cuts them out, in one image from the first
// piece's first row to the last row of any, and the COSMOS of them all
// (finish_view_analysis). The pieces' rows are final; they are different tracked parts, so no
// pixel is two pieces'. `excluded`: over the whole view.
PartView extract_group_view(const std::vector<BuiltPart>& pieces,
                            const PartRecognitionContext& context,
                            const std::vector<std::uint8_t>* excluded = nullptr);
// The first loop-frame column of the view extract_part_view cuts out of the builder.
int part_view_first_column(const BuiltPart& built);

struct PartRecognition {
  PartPose pose;
  RecognitionResult result;
  // For checks against a simulated ground truth: the pose on the belt, and the source's
  // profile indices of the part's first and last rows.
  RigidTransform T_belt_part;
  std::int64_t first_profile = 0;
  std::int64_t last_profile = -1;
  // The part's view in the loop frame (only its own pixels), when keep_part_image; else empty.
  // Its row 0 is profile `image_first_profile`: a blob's view spans the whole blob, of which
  // one part's rows are a stretch.
  RangeImage image;
  std::int64_t image_first_profile = 0;
};
PartRecognition recognize_part(const BuiltPart& built, const PartRecognitionContext& context,
                               std::int64_t part_seq);
// The same for a view already cut out (the blob's, or what remains of it once the parts
// recognized in it are taken away); `features_ms` is the time its analysis took. The view may
// hold touching parts, so it bounds no part's extent (part_size_gate.hpp: SceneParts).
PartRecognition recognize_part_view(const PartView& part, const BuiltPart& built,
                                    const PartRecognitionContext& context, std::int64_t part_seq,
                                    double features_ms);
// The pose of a recognition result in the loop frame, at the builder's last encoder count.
PartRecognition recognition_of(RecognitionResult result, const BuiltPart& built,
                               const PartRecognitionContext& context, std::int64_t part_seq);
// T_cell_part for a pose in the builder's loop frame, at the builder's last encoder count.
RigidTransform cell_pose_of(const RigidTransform& T_loop_part, const BuiltPart& built,
                            const PartRecognitionContext& context);
// A part whose rows span a fault of the source's stream (context.stream_faults), up to the
// builder's last row: ERROR, with the fault named. Applied once the tracker has completed the
// part, since a fault in the rows after its last data (a piece of it lost) counts too.
void mark_stream_fault(PartRecognition& recognition, const PartBuilder& builder,
                       const PartRecognitionContext& context);
// The same for a pose on the belt at encoder count e (the chain above).
RigidTransform cell_pose_of_belt(const RigidTransform& T_belt_part, std::int64_t encoder_ticks,
                                 const PartRecognitionContext& context);

// T_belt_part from a pose of T_cell_part at encoder count e (the inverse of the chain above).
RigidTransform belt_pose_of(const PartPose& pose, const RigidTransform& T_cell_scanner,
                            double mm_per_tick);

}  // namespace cosmos
