#pragma once
// The cell's recognizer thread (cell_runner.hpp): completed and speculative blobs to the
// recognizer workers (OrderedWorkers), groups of pieces (blob_groups.hpp), the results joined
// (piece_joiner.hpp) and numbered in the order the blobs completed, and the poses handed to
// the publisher; lost parts reported as ERROR poses.
#include "realtime/cell/cell_runner.hpp"
#include "realtime/cell/cell_threads_shared.hpp"
#include "realtime/cell/part_recognition.hpp"
#include "realtime/loop/scan_loop.hpp"
#include "realtime/rt/spsc_ring.hpp"

namespace cosmos {

// Runs until the acquisition is done and every blob is published.
void run_recognizer(ScanLoop& loop, const PartRecognitionContext& context,
                    SpscRing<CompletedPose>& poses, SharedStatus& status,
                    const CellRunSettings& settings);

}  // namespace cosmos
