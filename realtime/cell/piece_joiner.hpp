#pragma once
// The last step before poses go out: pieces of one part that the tracker kept apart are
// joined again. Across a gap that a part's own leading end can have shadowed, the tracker
// cannot tell a shadow-cut piece of the part (an elephant's trunk tip in front of its head)
// from a neighbour whose leading end shadows the part before it; it keeps the pieces apart,
// softly linked (part_tracker.hpp). Here a piece that nothing in the base explains (rejected)
// is held until the blobs around it are recognized: when a part recognized in one of them
// explains most of the piece's surface (explained_surface.hpp, in the loop frame all builders
// share), the piece is that part's and is not reported. Pieces that nothing explains alone
// are recognized together, as one range image of their surfaces (a part cut by its shadows
// into pieces none of which is recognizable); what is left is reported: one rejection per
// group of nearby pieces. Surface a blob's recognized parts leave unexplained is held the
// same way: a piece of a part that another blob holds (side by side, the tracker can split a
// part between two blobs) is that part's; only what no part explains is reported. A piece
// recognized on its own while the part it belongs to is recognized too (two poses for one part) is
// a duplicate: of two softly linked blobs whose parts explain each other, the smaller one's poses
// are dropped. A recognized blob waits for its soft successor only while one of its parts, as
// placed, reaches past the blob's last row into the shadow, or nearly failed recognition: a
// part clearly recognized that ends in its own blob is not continued behind it, and its pose
// goes out at once. The cell recognizes a chain of softly linked blobs as one group
// (recognize_blob_group), added here as one blob, so the soft links seen here are those no
// group could take: of a truncated blob, or of a group to a blob that did not join it.
#include <cstdint>
#include <deque>
#include <list>
#include <vector>

#include "core/range_image.hpp"
#include "realtime/cell/blob_recognition.hpp"

namespace cosmos {

struct JoinedRecognition {
  PartRecognition recognition;
  std::int64_t completed_ns = 0;  // when the tracker completed its blob
};

class PieceJoiner {
 public:
  explicit PieceJoiner(const PartRecognitionContext& context);

  // A recognized blob (the builder it came from, still held); returns what is now final,
  // in order (part_seq still to be assigned by the publisher of the poses).
  std::vector<JoinedRecognition> add(BlobRecognition blob, const PartBuilder& builder);
  // A group's blob (recognize_blob_group): the builders of its first and last pieces. Its
  // rows run from the first's first to the last's last, where its poses hold and its part
  // ends; the group is linked softly to what the first's predecessor and the last's successor
  // are.
  std::vector<JoinedRecognition> add(BlobRecognition blob, const PartBuilder& first,
                                     const PartBuilder& last);
  // The held pieces that no blob still to be added can join any more: every blob that starts
  // before `unfinished_from_profile` has been added (ScanLoop::unfinished_from_profile, and
  // none of the completed blobs still being recognized starts earlier). A piece waits for
  // the blobs near it, not for a count of blobs: on a sparse belt a count took seconds.
  std::vector<JoinedRecognition> release_settled(std::int64_t unfinished_from_profile);
  bool holding() const { return !held_.empty(); }
  // Recognized blobs held for their soft successor (the part behind, which may turn out to be
  // the same part): their poses wait for it to complete, however fast they were recognized.
  std::int64_t blobs_held_for_successor() const { return blobs_held_for_successor_; }
  // End of stream: everything still held.
  std::vector<JoinedRecognition> finish();

 private:
  struct Recognized {
    int part = -1;
    RigidTransform T_loop_part;
    std::int64_t first_profile = 0, last_profile = 0;
    double rms_mm = 0;  // its registration residual
  };
  struct Piece {
    std::vector<JoinedRecognition> rejections;  // or its poses, when recognized
    bool recognized = false;
    std::vector<Recognized> parts;  // recognized in it
    std::vector<Eigen::Vector3d> points_loop_mm;
    RangeImage image;
    std::int64_t first_profile = 0, last_profile = 0;
    int blobs_waited = 0;
    // A softly linked blob with nothing recognized: possibly a part cut by its shadows, which
    // nearby shadow pieces join (recognized together, or reported once). Other held pieces
    // (surface a blob's parts left unexplained, a blob the tracker kept apart outright) are
    // reported as they are unless a part explains them.
    bool shadow = false;
  };
  bool explained_by(const std::vector<Eigen::Vector3d>& points,
                    const std::vector<Recognized>& parts) const;
  bool explained_by_recent(const Piece& piece) const;
  // Whether the part, as placed, reaches past the blob's last profile: only then can the blob
  // behind, across a shadow, hold more of it.
  bool reaches_past(const Recognized& part, std::int64_t last_profile) const;
  // Whether its residual is well clear of the recognizer's rejection limit: a part that nearly
  // failed may be a piece of the part behind, fitted where it is not.
  bool clearly_recognized(const Recognized& part) const;
  bool near(const Piece& piece, const Recognized& part) const;
  bool near(const Piece& a, const Piece& b) const;
  // The held pieces near `piece` and `piece` as one image, recognized; on success the pieces
  // are taken out of held_ and the pose is returned.
  bool recognize_together(const Piece& piece, const PartBuilder& builder,
                          std::vector<JoinedRecognition>& out);
  void release(Piece& piece, std::vector<JoinedRecognition>& out);
  // Releases a held piece and takes it out of held_ (a shadow piece with the other shadow
  // pieces near it: one part none of them was recognized as); returns the next held piece.
  std::list<Piece>::iterator release_held(std::list<Piece>::iterator piece,
                                          std::vector<JoinedRecognition>& out);
  // Surface a blob's recognized parts left unexplained (BlobRecognition::remnants): not
  // reported when a part recognized earlier explains it, else held for the blobs to come.
  // Returns which of the blob's parts were taken (held or dropped).
  std::vector<std::uint8_t> hold_remnants(BlobRecognition& blob, const PartBuilder& builder);
  void remember(const Recognized& part);

  const PartRecognitionContext& context_;
  // A list: releasing a held piece first erases the other shadow pieces near it, and a
  // deque's erase would leave the piece being released dangling.
  std::list<Piece> held_;
  std::deque<Recognized> recent_;  // the parts recognized in the last few blobs
  std::int64_t blobs_held_for_successor_ = 0;
};

}  // namespace cosmos
