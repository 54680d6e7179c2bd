#pragma once
// The CSMP seed search's first pass (core/segmentation/seed_union_find.hpp) run on a part
// builder's rows as each row's shape index becomes final, so that at the part's end only the
// numbering of the seeds, growing, folding and refinement remain (segment_csmps_from_seeds).
// The nodes go into the rows' compact records, each row's crossings after them in the part's
// blocks (part_rows.hpp); nothing here allocates after construction.
//
// A builder's rows are whole rows of the belt, so the pass runs over every labelled pixel of
// them, other parts' as well. A part's view keeps only the pixels of the tracker ids it owns
// (realtime/cell/part_recognition.hpp); its sets are the sets the same pass makes over the
// view alone as long as no growing edge joined a pixel of the part to a pixel of an id the
// part does not own. Growing edges between different ids (where the tracker merged two pieces
// of a part, or a run it dropped) are listed, and holds_part refuses a part that one of them
// ties to an id it does not own: that part's view is searched whole. Pixel ids are raster
// ordered, row << 16 | column, as pass 1 needs.
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/segmentation/seed_union_find.hpp"
#include "core/segmentation/shape_seeds.hpp"
#include "core/surface/shape_index.hpp"
#include "realtime/loop/part_rows.hpp"

namespace cosmos {

class RowSeeds {
 public:
  RowSeeds(const SegmentationParameters& parameters, int width, int max_rows);

  // Starts a part: no row seeded, no pair of ids listed.
  void begin_part();
  // Pass 1 on the next row, whose planes (`planes`, full width; of the row above its labels,
  // which the builder's rings still hold, not its normals) are final, into its record; the record's
  // tracker ids must be set (the scan loop sets them when the row arrives, rows before its COSMOS
  // is final). The row's crossings go into the part's blocks (`store`, whose row the record is); a
  // part whose blocks had no room for them is searched in its view instead.
  void add_row(const SeedRowInput& planes, const PartRow& record, PartRows& store);

  int seeded_rows() const { return seeded_rows_; }
  // Whether pass 1 could keep everything for a part owning the ids `owns` accepts: the blocks
  // had room for every row's crossings, the listed pairs of ids did not overflow, and none
  // ties an owned id to one not owned.
  template <class Owns>
  bool holds_part(Owns owns) const {
    if (!enabled_ || crossings_lost_ || pairs_overflowed_) return false;
    for (int n = 0; n < pair_count_; ++n)
      if (owns(linked_ids_[n].first) != owns(linked_ids_[n].second)) return false;
    return true;
  }
  // The seeds of a view cut out of rows [0, view.height()) of the builder, its column 0 the
  // builder's `first_column`, holding only the part's pixels (a pixel of the view is the
  // part's where its label is valid): find_shape_seeds of the view, from the nodes pass 1
  // left. Empty when not all the view's rows are seeded or a set reaches outside the view.
  // Call it only for a part that holds_part accepts.
  std::optional<ShapeSeeds> view_seeds(const ShapeIndexField& view, int first_column) const;

  static constexpr int kMaxLinkedIdPairs = 16;

 private:
  using Crossing = std::pair<std::int32_t, std::int32_t>;  // pixel ids
  struct RowNodes {
    SeedNode* nodes = nullptr;  // null: a row without samples
    int column_begin = 0;
    int column_end = 0;
    Crossing* crossings = nullptr;
    int crossing_count = 0;
  };
  // The nodes of one row as pass 1 reads them (seed_union_find.hpp).
  struct Nodes {
    RowNodes* rows;
    int row;
    std::int32_t id(int column) const { return row << kColumnBits | column; }
    std::int32_t above_id(int column) const { return (row - 1) << kColumnBits | column; }
    SeedNode& at(std::int32_t id) {
      const RowNodes& r = rows[id >> kColumnBits];
      return r.nodes[(id & kColumnMask) - r.column_begin];
    }
    SeedNode& here(int column) { return rows[row].nodes[column - rows[row].column_begin]; }
    SeedNode& above(int column) { return rows[row - 1].nodes[column - rows[row - 1].column_begin]; }
  };
  static constexpr int kColumnBits = 16;
  static constexpr std::int32_t kColumnMask = (1 << kColumnBits) - 1;

  void list_linked_ids(int row, const PartRow& record, const std::uint8_t* edges);

  bool enabled_;  // the ids fit (width <= 2^16, max_rows < 2^15)
  int width_;
  float quantum_;
  double crease_cos_;
  std::vector<RowNodes> rows_;  // max_rows
  // The row above's normals, kept as the builder's rings move on (its smoothing may have
  // overwritten them by the time this row is final).
  std::array<std::vector<float>, 3> normal_above_;
  std::vector<std::int64_t> ids_above_, ids_;                 // tracker ids, -1 outside the samples
  std::array<int, 2> ids_above_span_{0, 0}, ids_span_{0, 0};  // the columns holding ids
  std::vector<std::uint8_t> edges_, same_id_;
  std::vector<Crossing> row_crossings_;  // a row's, at most one per backward neighbour
  std::array<std::pair<std::int64_t, std::int64_t>, kMaxLinkedIdPairs> linked_ids_{};
  int pair_count_ = 0;
  bool pairs_overflowed_ = false;
  bool crossings_lost_ = false;
  Crossing last_crossing_{-1, -1};
  int seeded_rows_ = 0;
};

}  // namespace cosmos
