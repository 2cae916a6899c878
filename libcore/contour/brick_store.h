// Storage for the per-brick tables of one contour: large blocks, filled in
// turn and dropped whole. Blocks are allocated without being zeroed and are
// large enough that the allocator maps them from (and returns them to) the
// system, so dropping a store lowers the resident set at once, which many
// small per-brick vectors would not.
#pragma once

#include <cstddef>
#include <cstring>
#include <memory>
#include <vector>

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
    used_ = capacity_ = 0;
  }

 private:
  static constexpr size_t kBlock = size_t(64) << 20;  // above any mmap threshold
  void* allocate(size_t bytes) {
    bytes = (bytes + 15) & ~size_t(15);
    if (used_ + bytes > capacity_) {
      capacity_ = bytes > kBlock ? bytes : kBlock;
      blocks_.emplace_back(new char[capacity_]);
      used_ = 0;
    }
    void* at = blocks_.back().get() + used_;
    used_ += bytes;
    return at;
  }

  std::vector<std::unique_ptr<char[]>> blocks_;
  size_t used_ = 0, capacity_ = 0;
};

// One thread's stores: vertex data (points, gradients) is dropped before
// the face data (triangles, shared keys) that the topology still needs.
struct BrickStores {
  BlockStore vertices, faces;
};

}  // namespace isoform
