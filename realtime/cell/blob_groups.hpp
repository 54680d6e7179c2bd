#pragma once
// Which completed blobs the cell recognizes together, as one group (recognize_blob_group,
// blob_recognition.hpp). A blob too small to be a part alone (under blob.min_stretch_fraction
// of a typical view's area, as the stretches of a blob recognized on their own) that the
// tracker linked softly to a blob after it (part_tracker.hpp) is a piece of a part its shadow
// cut: a feature in front of the part. It and the blobs linked on from it, to any of its
// pieces, are one group. Two blobs each large enough to be a part are not grouped: softly
// linked neighbours on a dense belt, recognized apart at once on two workers, whose
// duplicates the joiner drops. A group is open while a piece's successor may still come: a
// successor starts by the row at which its piece completed, so once every part that started
// by then has completed (ScanLoop::unfinished_from_profile) it has joined or is gone (merged
// into another part, lost). The groups follow from the tracker alone, never from timing.
#include <array>
#include <cstdint>
#include <deque>
#include <vector>

#include "realtime/loop/scan_loop.hpp"

namespace cosmos {

// What grouping reads of a completed blob: its tracker ids and links, size and completion.
struct BlobLinks {
  std::int64_t part_id = -1;
  std::array<std::int64_t, kMaxMergedIds> merged_ids{};
  int merged_count = 0;
  std::int64_t soft_link_of = -1;
  bool has_soft_successor = false;
  bool truncated = false;
  std::int64_t pixels = 0;
  std::int64_t completed_profile = 0;

  bool owns(std::int64_t id) const;
};
BlobLinks links_of(const PartBuilder& builder);

class BlobGroups {
 public:
  // `builders`: the loop's builder count (blobs are its builder indices); a blob of fewer than
  // `small_piece_pixels` pixels is no part alone.
  BlobGroups(int builders, double small_piece_pixels);

  // The blob `index` completed (`completed`: the blobs completed and not yet published, oldest
  // first, this one among them): it joins the open group one of whose pieces owns its soft
  // link, or starts one when it is small and a later blob may continue it.
  void add_completed(int index, const BlobLinks& links, const std::deque<int>& completed);
  // The first piece of the open group one of whose pieces (among `completed`) owns the tracker
  // id `link`, or -1.
  int open_group_continued_by(std::int64_t link, const std::deque<int>& completed) const;
  // Closes the group whose first piece is `first` once no piece's successor can still come.
  void close_if_settled(int first, std::int64_t unfinished_from_profile);
  // The first piece of the blob's group, -1 when it is in none.
  int first_of(int index) const { return first_of_[static_cast<std::size_t>(index)]; }
  bool open(int first) const { return open_[static_cast<std::size_t>(first)] != 0; }
  // The group's pieces in the order they completed (first piece first).
  const std::vector<int>& pieces(int first) const {
    return pieces_[static_cast<std::size_t>(first)];
  }
  // How many of `completed` (oldest first) wait on a part still open: from the first open
  // group's first piece on, since blobs are published in the order they completed.
  int waiting_on_open_parts(const std::deque<int>& completed) const;
  // The blob was published: it leaves its group.
  void leave(int index) { first_of_[static_cast<std::size_t>(index)] = -1; }

 private:
  double small_piece_pixels_;
  std::vector<BlobLinks> links_;
  std::vector<int> first_of_;
  std::vector<std::vector<int>> pieces_;
  std::vector<std::uint8_t> open_;
};

}  // namespace cosmos
