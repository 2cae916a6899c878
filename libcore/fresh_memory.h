// Large arrays that the contour and the curvature write in full: their
// pages are made present a stretch at a time (Linux madvise
// MADV_POPULATE_WRITE) before they are written, instead of by one page fault
// per 4 KB page on first write, which adds a fault's entry and exit to the
// kernel's time for every page it zeroes. Where asked, the whole 2 MB pages
// inside the range are asked for first (MADV_HUGEPAGE: one fault and one
// zeroing per 2 MB). Elsewhere, or when the kernel refuses, the pages fault
// in as usual: the contents and the result never depend on it.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

namespace isoform {

// Makes the whole pages inside [p, p + bytes) present and writable, in 2 MB
// pages where huge is true and the system allows them. Ranges under 128 KB
// are left alone. Runs in parallel with TBB in the calling arena when
// parallel is true, in at least 4 stretches.
void populate_pages(void* p, size_t bytes, bool parallel = true, bool huge = false);

// Bytes mapped from the system and given back to it when destroyed, at any
// size (Linux: an anonymous mapping; the allocator would keep any block below
// its mapping threshold in its heap, resident after it is freed, where this
// class keeps a bounded few, below).
// Elsewhere, or when the mapping fails, an ordinary allocation. Not
// initialised as far as the caller is concerned. The whole 2 MB pages inside
// a mapping are asked for as 2 MB pages (MADV_HUGEPAGE).
//
// Mappings of at most kCachedBlock bytes are kept, up to kCacheBytes in all
// for the whole process, when they are destroyed, and a new block of the
// same size takes one of them: its pages are then present already. A
// contour of a small volume maps a few such blocks per call, and making
// their pages present again costs more than the contour's own work on them
// where a first touch is slow (each 4 KB page a fault and a zeroing of its
// own, against a few instructions of the contour's per value). Thread-safe.
class SystemBlock {
 public:
  static constexpr size_t kCachedBlock = size_t(4) << 20;
  static constexpr size_t kCacheBytes = size_t(16) << 20;

  explicit SystemBlock(size_t bytes);
  ~SystemBlock();
  SystemBlock(const SystemBlock&) = delete;
  SystemBlock& operator=(const SystemBlock&) = delete;
  char* data() const { return data_; }

 private:
  char* data_ = nullptr;
  size_t bytes_ = 0;
  bool mapped_ = false;
};

// Unmaps the mappings SystemBlock keeps; returns how many bytes they held.
size_t release_kept_blocks();

// The bytes a ScratchArray maps for `bytes`: rounded up to a power of two,
// 64 KB at least, up to SystemBlock::kCachedBlock; larger sizes as they are.
size_t scratch_bytes(size_t bytes);

// n values of T, not initialised, for one call's scratch, in a SystemBlock
// of scratch_bytes(n * sizeof(T)): the rounding lets the next call's array
// of a like size take the block this one leaves (SystemBlock keeps it),
// pages present. Larger arrays get their pages made present up front, in
// 2 MB pages where the system allows. T must be trivially copyable.
template <class T>
class ScratchArray {
  static_assert(std::is_trivially_copyable<T>::value, "ScratchArray holds trivially copyable values only");

 public:
  ScratchArray() = default;
  explicit ScratchArray(size_t n) : block_(std::make_unique<SystemBlock>(scratch_bytes(n * sizeof(T)))) {
    if (n * sizeof(T) > SystemBlock::kCachedBlock) populate_pages(block_->data(), n * sizeof(T), true, true);
  }
  T* get() const { return block_ ? reinterpret_cast<T*>(block_->data()) : nullptr; }
  T& operator[](size_t i) const { return get()[i]; }
  void reset() { block_.reset(); }

 private:
  std::unique_ptr<SystemBlock> block_;
};

// n values, not initialised, their pages present.
template <class T>
std::unique_ptr<T[]> fresh_array(size_t n, bool parallel = true, bool huge = false) {
  std::unique_ptr<T[]> a(new T[n]);
  populate_pages(a.get(), n * sizeof(T), parallel, huge);
  return a;
}

// v resized to n value-initialised elements (v empty before), its pages
// made present before they are written.
template <class T>
void fresh_resize(std::vector<T>& v, size_t n, bool parallel = true, bool huge = false) {
  v.reserve(n);
  populate_pages(v.data(), n * sizeof(T), parallel, huge);
  v.resize(n);
}

}  // namespace isoform
