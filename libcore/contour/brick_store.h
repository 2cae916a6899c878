// Storage for the per-brick tables of one contour: blocks filled in turn
// and dropped whole, each mapped from the system and given back to it when
// dropped (fresh_memory.h), so dropping a store lowers the resident set at
// once, which many small per-brick vectors would not; the process keeps a
// few small blocks for the next contour (SystemBlock). The first block of a
// store is small and each next one twice the last, up to 64 MB: a small
// contour maps and touches little memory, a large one soon gets large
// blocks.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <memory>
#include <vector>

#include "../fresh_memory.h"

namespace isoform {

class BlockStore {
 public:
  // A copy of n values at from, aligned to 16 bytes; valid until clear().
  template <class T>
  const T* copy(const T* from, size_t n) {
    if (n == 0) return nullptr;
    void* to = allocate(n * sizeof(T));
    std::memcpy(to, from, n * sizeof(T));
    return static_cast<const T*>(to);
  }
  void clear() {
    blocks_.clear();
    used_ = capacity_ = populated_ = 0;
    next_block_ = kFirstBlock;
  }

 private:
  static constexpr size_t kFirstBlock = size_t(1) << 20;
  static constexpr size_t kBlock = size_t(64) << 20;
  static constexpr size_t kAhead = size_t(2) << 20;   // pages made present at a time
  void* allocate(size_t bytes) {
    bytes = (bytes + 15) & ~size_t(15);
    if (used_ + bytes > capacity_) {
      capacity_ = std::max(bytes, next_block_);
      next_block_ = std::min(2 * next_block_, kBlock);
      blocks_.push_back(std::make_unique<SystemBlock>(capacity_));
      used_ = populated_ = 0;
    }
    char* block = blocks_.back()->data();
    if (used_ + bytes > populated_) {
      // The pages about to be written, and the next few, in one call
      // (fresh_memory.h), on this thread.
      const size_t upto = std::min(capacity_, used_ + bytes + kAhead);
      populate_pages(block + populated_, upto - populated_, false);
      populated_ = upto;
    }
    void* at = block + used_;
    used_ += bytes;
    return at;
  }

  std::vector<std::unique_ptr<SystemBlock>> blocks_;
  size_t used_ = 0, capacity_ = 0, populated_ = 0;
  size_t next_block_ = kFirstBlock;  // the size of the next block
};

// One thread's stores: vertex data (points, gradients) is dropped before
// the face data (triangles, shared keys) that the topology still needs.
struct BrickStores {
  BlockStore vertices, faces;
};

}  // namespace isoform
