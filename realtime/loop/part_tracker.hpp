#pragma once
// Tracks parts on the belt across conditioned rows: connected components of data pixels,
// row by row. Each row's runs of data link to the open parts whose previous-row runs they
// overlap (8-connectivity plus a small column tolerance); runs touching no open part start a
// part; a run touching two parts merges them (the later into the earlier, reported); a part
// that no run has touched for link_gap_rows rows is complete, unless its footprint (bounding
// box, grown by the link gaps) overlaps an open part's: then it merges into it. Several
// non-touching parts may be under the scanner at once, as long as their footprints do not
// overlap. All storage is sized at construction: adding a row never allocates.
#include <cstdint>
#include <vector>

#include "core/parameter_visitor.hpp"

namespace cosmos {

struct PartTrackerParameters {
  int max_open_parts = 16;    // more at once: the extra runs are dropped and counted
  int max_runs_per_row = 64;  // more runs in a row: the extra are dropped and counted
  int link_gap_columns = 1;   // runs this many columns apart still touch (speckle gaps)
  // A part stays open this many rows without data, and a run within its column extent
  // (± link_gap_columns) in that time joins it: laser shadows and dropouts split a part's
  // surface into pieces a few millimetres apart. 0: only touching runs continue a part.
  int link_gap_rows = 0;
  // Completed components with fewer pixels, spanning fewer rows and fewer columns than this,
  // are noise (specks).
  std::int64_t min_pixels = 50;
  // The camera's occlusion shadow, rows of belt per mm of height (tan of the triangulation
  // angle over the belt step; the scan loop sets it from the scanner, it is no config key).
  // Above 0, pieces link across no-data rows only as far as a shadow can reach: the shadow
  // lies downstream of (in rows before) the feature that casts it, so a run after a gap
  // of g rows continues a part only if its height could have shadowed g rows, and two
  // a longer gap, or belt seen in it, is two parts. Pieces a shadow can join are linked
  // softly (TrackedPart::soft_link_of), not merged. 0: the fixed link_gap_rows alone.
  double shadow_rows_per_mm = 0;
  // With shadow_rows_per_mm: gaps of up to this many rows join outright (dropouts, a part's
  // shadow-cut pieces close together); longer ones link softly. Below the gap of parts that
  // must come out separate (2 mm: 5 rows at 0.4 mm).
  int hard_link_gap_rows = 2;

  template <class Visitor>
  void visit(Visitor& v) {
    v("max_open_parts", max_open_parts, "parts open at once; more: runs dropped and counted",
      Range{1, 4096});
    v("max_runs_per_row", max_runs_per_row, "runs of data per row; more: dropped and counted",
      Range{1, 65536});
    v("link_gap_columns", link_gap_columns, "runs this many columns apart still touch",
      Range{0, 65536});
    v("link_gap_rows", link_gap_rows, "rows a part stays open without data", Range{0, 65536});
    v("hard_link_gap_rows", hard_link_gap_rows,
      "no-data rows a part's pieces join across outright; longer gaps its shadow explains "
      "link softly (kept apart until recognition)",
      Range{0, 65536});
    v("min_pixels", min_pixels,
      "completed components with fewer pixels, spanning fewer rows and fewer columns, are "
      "noise",
      Range{0, 1099511627776.0});  // 2^40
  }
};

struct TrackedPart {
  std::int64_t id = -1;  // increasing, never reused
  std::int64_t first_row = 0;
  std::int64_t last_row = 0;
  int column_min = 0;
  int column_max = 0;
  std::int64_t pixels = 0;
  float max_z_mm = 0;      // highest sample above the belt
  float leading_z_mm = 0;  // highest sample of its first kLeadingRows rows
  // With shadow_rows_per_mm: the earlier piece this one may continue across a gap its own
  // leading end can have shadowed (-1 none), and whether a later piece links to this one.
  // Pieces so linked stay separate parts: only recognition can tell a part's shadow-cut
  // piece from a neighbour whose leading end shadows the part before it.
  std::int64_t soft_link_of = -1;
  bool has_soft_successor = false;
  std::int64_t merged_into = -1;  // completed by merging into this part
  bool noise = false;             // a speck: fewer than min_pixels pixels, rows and columns
};

// The cell's tracking: pieces of one part up to 25 columns (10 mm) and 75 rows (30 mm) apart
// are one part. Along the belt the camera's occlusion shadow in front of a raised feature is up
// to its height x tan(triangulation angle): an elephant's trunk 50 mm up at 30 degrees is cut
// off from the body by ~29 mm of no data. With shadow_rows_per_mm (the cell's scan loop sets
// it) a gap joins only what such a shadow can explain, so parts a few millimetres apart with
// low leading ends come out separate; parts whose leading end shadows the part before them are
// one blob, which scene-level recognition takes apart (realtime/cell/blob_recognition.hpp).
// The price of the 30 mm is that a part completes 30 mm of belt after its last row.
inline PartTrackerParameters cell_part_tracking() {
  PartTrackerParameters parameters;
  parameters.link_gap_columns = 25;
  parameters.link_gap_rows = 75;
  return parameters;
}

class PartTracker {
 public:
  // The rows at a part's downstream end whose height casts the shadow in front of it.
  static constexpr int kLeadingRows = 8;

  PartTracker(const PartTrackerParameters& parameters, int width);

  // Labels the row's data pixels (non-NaN) with their part id; returns the parts completed
  // by this row (valid until the next call): those merged into another first, newest first,
  // then the others, oldest first.
  // `belt` (optional, one flag per column): where the belt itself was seen. With it, no-data
  // rows are a shadow only where no belt showed: a part never links across belt.
  const std::vector<TrackedPart>& add_row(const float* z_mm, std::int64_t row_index,
                                          const std::uint8_t* belt = nullptr);

  const std::vector<std::int64_t>& row_labels() const { return labels_; }  // -1: background
  const std::vector<TrackedPart>& open_parts() const { return open_; }
  std::int64_t dropped_runs() const { return dropped_runs_; }

 private:
  struct Run {
    int begin;  // first column
    int end;    // one past the last column
    std::int64_t part;
  };
  int open_index(std::int64_t part) const;
  std::int64_t resolve(std::int64_t part) const;
  void merge(std::int64_t keep, std::int64_t absorbed);
  bool idle(const TrackedPart& part, std::int64_t row_index) const;
  // A piece about to complete with fewer than min_pixels pixels and a piece softly linked
  // after it: joined with it. Softly linked pieces stay apart so that recognition can tell a
  // neighbour from a shadow-cut piece, but a piece too small to be a part can only be a piece
  // of the part its shadows cut: a thin part seen edge-on, rising along the belt, is cut by
  // its own shadow into specks each far below min_pixels, which alone would all be noise.
  void join_small_pieces(std::int64_t row_index);
  bool footprints_overlap(const TrackedPart& a, const TrackedPart& b) const;
  // Rows of no data a feature of height z_mm can shadow in front of it (shadow_rows_per_mm
  // with a margin for the perspective and the height of the surface it falls on).
  std::int64_t shadow_rows(float z_mm) const;
  // A row by which belt showed in most (70 %) of columns [begin, end): -1 none.
  std::int64_t belt_seen_row(int begin, int end);

  PartTrackerParameters parameters_;
  int width_;
  std::int64_t next_id_ = 0;
  std::vector<Run> previous_runs_, runs_;
  std::vector<TrackedPart> open_, completed_;
  std::vector<std::int64_t> labels_;
  std::vector<std::int64_t> belt_row_;  // per column: the last row that showed belt, -1 none
  std::vector<std::int64_t> scratch_;   // width, for belt_seen_row
  std::vector<std::pair<std::int64_t, std::int64_t>> merges_;  // absorbed -> kept, this row
  std::int64_t dropped_runs_ = 0;
};

}  // namespace cosmos
