// The reduction's large arrays on 2 MB pages.
//
// NOTE: the removals read their faces, vertices, face lists and tracked
// original vertices in weight order, all over arrays of tens of megabytes:
// with 4 KB pages nearly every such read also misses the address
// translation cache, and every first write of a page is a page fault of its
// own. An array of 2 MB or more is therefore mapped on its own, aligned to
// 2 MB and marked for transparent huge pages (madvise; the kernel may still
// give 4 KB pages, and nothing but timing depends on it). Smaller arrays use
// the ordinary allocator. Where the kernel is set to compact memory for such
// regions (its defrag setting `madvise`), a first write may wait for a
// 2 MB page to be freed up: the reduction allocates these arrays once per
// call, a few dozen of them.
//
// NOTE: a freed array's mapping is kept, its pages marked lazily free
// (MADV_FREE: the system takes them back when it needs memory, without
// writing them anywhere), and the next array that fits takes it, cut to
// its size: a second reduction in the same process (the Blender add-on, a
// bench's repeated calls) finds its pages present instead of asking the
// kernel to clear about 150 MB again for a 1M-triangle mesh: the kernel
// zeroes every fresh page at its first write, one fault a page, and for
// such arrays that is a large share of a whole call. At most kBigKeptBytes
// are kept, the oldest given back first. The contents of a kept page are
// left over or zero: the vectors write before they read.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace isoform::reduce {

// At least 2 MB, mapped as described above; throws std::bad_alloc.
void* allocate_big(size_t bytes);
void free_big(void* p, size_t bytes);
constexpr size_t kBigBytes = size_t(2) << 20;
constexpr size_t kBigKeptBytes = size_t(1) << 30;
// Unmaps the freed arrays' mappings kept for the next ones; returns their bytes.
size_t release_kept_big();

template <class T>
struct BigAllocator {
  using value_type = T;
  BigAllocator() = default;
  template <class U>
  BigAllocator(const BigAllocator<U>&) {}
  T* allocate(size_t n) {
    if (n * sizeof(T) < kBigBytes) return std::allocator<T>().allocate(n);
    return static_cast<T*>(allocate_big(n * sizeof(T)));
  }
  void deallocate(T* p, size_t n) {
    if (n * sizeof(T) < kBigBytes) return std::allocator<T>().deallocate(p, n);
    free_big(p, n * sizeof(T));
  }
  template <class U>
  bool operator==(const BigAllocator<U>&) const { return true; }
  template <class U>
  bool operator!=(const BigAllocator<U>&) const { return false; }
};

template <class T>
using BigVector = std::vector<T, BigAllocator<T>>;

}  // namespace isoform::reduce
