#pragma once
// The recognizer worker's step for one completed part: the part's view cut out of its
// builder (rows of the part, columns of its tracked extent plus a margin, pixels of other
// parts masked out), the rest of the chapter-3 pipeline on the builder's finished fields
// (finish_view_analysis, the very code that ends analyze_view, so the features equal
// whole-image processing of the part's rows), recognition
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
};

// The part's range image and chapter-3 analysis in the loop frame.
struct PartView {
  RangeImage image;
  ViewAnalysis analysis;
};
// Finishes the builder's COSMOS first: the pipeline's last rows (up to the smoothing depth)
// are drained here, on the recognizer's thread, rather than in the acquisition thread's
// profile that completed the part: draining them is the work of many rows at once, far more
// than one line period allows.
PartView extract_part_view(PartBuilder& builder, const PartRecognitionContext& context);

struct PartRecognition {
  PartPose pose;
  RecognitionResult result;
  // For checks against a simulated ground truth: the pose on the belt, and the source's
  // profile indices of the part's first and last rows.
  RigidTransform T_belt_part;
  std::int64_t first_profile = 0;
  std::int64_t last_profile = -1;
  // The part's view in the loop frame (only its own pixels), when keep_part_image; else empty.
  RangeImage image;
};
PartRecognition recognize_part(PartBuilder& builder, const PartRecognitionContext& context,
                               std::int64_t part_seq);

// T_belt_part from a pose of T_cell_part at encoder count e (the inverse of the chain above).
RigidTransform belt_pose_of(const PartPose& pose, const RigidTransform& T_cell_scanner,
                            double mm_per_tick);

}  // namespace cosmos
