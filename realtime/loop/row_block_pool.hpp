#pragma once
// The memory the part builders keep their finished rows in (part_rows.hpp): one arena of
// equal blocks, allocated once when the scan loop is built, handed out and taken back a
// block at a time by the acquisition thread alone. A builder takes blocks as its part grows
// and gives them back when the recognizer returns it, so what the builders hold follows the
// parts on the belt instead of the longest part times the number of builders.
//
// The arena is written once when it is allocated, so all of it is resident from the start:
// the cell's memory is what its settings state from the first part on, instead of creeping
// up with the most blocks ever used at once, and the acquisition thread never takes a
// first-touch page fault on a block.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace cosmos {

class RowBlockPool {
 public:
  // Blocks are rounded up to whole 64-byte lines, so every block is as aligned as the arena
  // (operator new's 16 bytes: enough for any row plane).
  RowBlockPool(int block_count, std::size_t block_bytes);

  // A free block, or -1 when every block is taken. Never allocates.
  int acquire();
  void release(int block);

  std::byte* data(int block) {
    return arena_.get() + static_cast<std::size_t>(block) * block_bytes_;
  }
  std::size_t block_bytes() const { return block_bytes_; }
  int block_count() const { return block_count_; }
  int blocks_in_use() const { return block_count_ - static_cast<int>(free_.size()); }
  // The most blocks ever in use at once: how much of the pool the belt has needed.
  int peak_blocks_in_use() const { return peak_in_use_; }
  std::size_t bytes() const { return static_cast<std::size_t>(block_count_) * block_bytes_; }

 private:
  int block_count_;
  std::size_t block_bytes_;
  std::unique_ptr<std::byte[]> arena_;
  std::vector<int> free_;  // stack: the most recently released block is reused first
  int peak_in_use_ = 0;
};

}  // namespace cosmos
