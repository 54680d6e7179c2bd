#include "realtime/loop/row_block_pool.hpp"

#include <algorithm>

namespace cosmos {

namespace {

constexpr std::size_t kBlockAlignment = 64;

}  // namespace

RowBlockPool::RowBlockPool(int block_count, std::size_t block_bytes)
    : block_count_(std::max(block_count, 0)),
      block_bytes_((std::max<std::size_t>(block_bytes, 1) + kBlockAlignment - 1) / kBlockAlignment *
                   kBlockAlignment),
      // Value-initialized: zeroing the arena touches every page of it now.
      arena_(new std::byte[static_cast<std::size_t>(block_count_) * block_bytes_]()) {
  free_.reserve(static_cast<std::size_t>(block_count_));
  // Block 0 on top: a lightly used pool keeps reusing the same few blocks.
  for (int block = block_count_ - 1; block >= 0; --block) free_.push_back(block);
}

int RowBlockPool::acquire() {
  if (free_.empty()) return -1;
  const int block = free_.back();
  free_.pop_back();
  peak_in_use_ = std::max(peak_in_use_, blocks_in_use());
  return block;
}

void RowBlockPool::release(int block) { free_.push_back(block); }

}  // namespace cosmos
