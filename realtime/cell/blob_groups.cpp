#include "realtime/cell/blob_groups.hpp"

#include <algorithm>
#include <iterator>

namespace cosmos {

bool BlobLinks::owns(std::int64_t id) const {
  return owns_tracker_id(part_id, merged_ids, merged_count, id);
}

BlobLinks links_of(const PartBuilder& builder) {
  BlobLinks links;
  links.part_id = builder.part_id;
  links.merged_ids = builder.merged_ids;
  links.merged_count = builder.merged_count;
  links.soft_link_of = builder.soft_link_of;
  links.has_soft_successor = builder.has_soft_successor;
  links.truncated = builder.truncated;
  links.pixels = builder.pixels;
  links.completed_profile = builder.completed_profile;
  return links;
}

BlobGroups::BlobGroups(int builders, double small_piece_pixels)
    : small_piece_pixels_(small_piece_pixels),
      links_(static_cast<std::size_t>(builders)),
      first_of_(static_cast<std::size_t>(builders), -1),
      pieces_(static_cast<std::size_t>(builders)),
      open_(static_cast<std::size_t>(builders), 0) {}

int BlobGroups::open_group_continued_by(std::int64_t link, const std::deque<int>& completed) const {
  if (link < 0) return -1;
  for (const int earlier : completed) {
    const int first = first_of(earlier);
    if (first >= 0 && open(first) && links_[static_cast<std::size_t>(earlier)].owns(link))
      return first;
  }
  return -1;
}

void BlobGroups::add_completed(int index, const BlobLinks& links,
                               const std::deque<int>& completed) {
  const auto k = static_cast<std::size_t>(index);
  links_[k] = links;
  first_of_[k] = -1;
  const int first = open_group_continued_by(links.soft_link_of, completed);
  if (first >= 0) {
    first_of_[k] = first;
    pieces_[static_cast<std::size_t>(first)].push_back(index);
    return;
  }
  if (links.has_soft_successor && !links.truncated &&
      static_cast<double>(links.pixels) < small_piece_pixels_) {
    first_of_[k] = index;
    pieces_[k] = {index};
    open_[k] = 1;
  }
}

void BlobGroups::close_if_settled(int first, std::int64_t unfinished_from_profile) {
  const std::vector<int>& group = pieces(first);
  if (std::none_of(group.begin(), group.end(), [&](int piece) {
        const BlobLinks& links = links_[static_cast<std::size_t>(piece)];
        return links.has_soft_successor && !links.truncated &&
               unfinished_from_profile <= links.completed_profile;
      }))
    open_[static_cast<std::size_t>(first)] = 0;
}

int BlobGroups::waiting_on_open_parts(const std::deque<int>& completed) const {
  const auto first_waiting = std::find_if(completed.begin(), completed.end(), [&](int done) {
    const int first = first_of(done);
    return first >= 0 && open(first);
  });
  return static_cast<int>(std::distance(first_waiting, completed.end()));
}

}  // namespace cosmos
