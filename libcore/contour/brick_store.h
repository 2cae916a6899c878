// Storage for the per-brick tables of one contour: large blocks, filled in
// turn and dropped whole. Blocks are allocated without being zeroed and are
// large enough that the allocator maps them from (and returns them to) the
// system, so dropping a store lowers the resident set at once, which many
// small per-brick vectors would not.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <memory>
#include <vector>

#include "fresh_memory.h"

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
  }

 private:
  static constexpr size_t kBlock = size_t(64) << 20;  // above any mmap threshold
  static constexpr size_t kAhead = size_t(2) << 20;   // pages made present at a time
  void* allocate(size_t bytes) {
    bytes = (bytes + 15) & ~size_t(15);
    if (used_ + bytes > capacity_) {
      capacity_ = bytes > kBlock ? bytes : kBlock;
      blocks_.emplace_back(new char[capacity_]);
      used_ = populated_ = 0;
    }
    char* block = blocks_.back().get();
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

  std::vector<std::unique_ptr<char[]>> blocks_;
  size_t used_ = 0, capacity_ = 0, populated_ = 0;
};

// One thread's stores: vertex data (points, gradients) is dropped before
// the face data (triangles, shared keys) that the topology still needs.
struct BrickStores {
  BlockStore vertices, faces;
};

}  // namespace isoform
