// Populating fresh pages (fresh_memory.h).
#include "fresh_memory.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace isoform {
namespace {

// Asks for 2 MB pages over the whole 2 MB pages inside [p, p + bytes) (the
// pieces at its ends may share their 2 MB with other allocations). A
// refusal changes nothing.
void advise_huge(void* p, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr uintptr_t kHuge = uintptr_t(2) << 20;
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

}  // namespace

void populate_pages(void* p, size_t bytes, bool parallel, bool huge) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr size_t kSmall = size_t(128) << 10;  // below this, faults are cheap enough
  constexpr size_t kStretch = size_t(8) << 20;  // one call per stretch, at most
  if (!p || bytes < kSmall) return;
  static const size_t page = size_t(sysconf(_SC_PAGESIZE));
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(p) + page - 1) & ~uintptr_t(page - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~uintptr_t(page - 1);
  if (end <= begin) return;
  if (huge) advise_huge(reinterpret_cast<void*>(begin), end - begin);
  // NOTE: in parallel, at least 4 stretches, so that the pages of a
  // contour's small output arrays (headsq: 0.3-1 MB each, their faults a
  // visible share of such a short call) fault in on every thread, not on one.
  size_t stretch = kStretch;
  if (parallel) stretch = std::min(kStretch, std::max(page, ((end - begin) / 4 + page - 1) & ~(page - 1)));
  const size_t stretches = (end - begin + stretch - 1) / stretch;
  const auto one = [&](size_t s) {
    const uintptr_t a = begin + s * stretch;
    const uintptr_t b = a + stretch < end ? a + stretch : end;
    // A refusal (old kernel, no memory to populate now) leaves the pages
    // to fault in when written.
    (void)madvise(reinterpret_cast<void*>(a), b - a, MADV_POPULATE_WRITE);
  };
  if (parallel && stretches > 1)
    tbb::parallel_for(size_t(0), stretches, one);
  else
    for (size_t s = 0; s < stretches; ++s) one(s);
#else
  (void)p;
  (void)bytes;
  (void)parallel;
  (void)huge;
#endif
}

namespace {

// The kept mappings (SystemBlock). Made once and never destroyed, so that a
// block freed while the process exits still finds it.
class BlockCache {
 public:
  static BlockCache& get() {
    static BlockCache* cache = new BlockCache;
    return *cache;
  }
  // A kept mapping of exactly `bytes`, or null.
  void* take(size_t bytes) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t i = 0; i < kept_.size(); ++i)
      if (kept_[i].second == bytes) {
        void* p = kept_[i].first;
        kept_[i] = kept_.back();
        kept_.pop_back();
        held_ -= bytes;
        return p;
      }
    return nullptr;
  }
  // True when the mapping is kept (then the caller must not unmap it).
  bool keep(void* p, size_t bytes) {
    if (bytes > SystemBlock::kCachedBlock) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    if (held_ + bytes > SystemBlock::kCacheBytes) return false;
    kept_.emplace_back(p, bytes);
    held_ += bytes;
    return true;
  }
  // Every kept mapping, handed over (the cache is empty after).
  std::vector<std::pair<void*, size_t>> take_all() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::pair<void*, size_t>> all;
    all.swap(kept_);
    held_ = 0;
    return all;
  }

 private:
  std::mutex mutex_;
  std::vector<std::pair<void*, size_t>> kept_;
  size_t held_ = 0;
};

}  // namespace

size_t scratch_bytes(size_t bytes) {
  if (bytes > SystemBlock::kCachedBlock) return bytes;
  size_t size = size_t(64) << 10;
  while (size < bytes) size *= 2;
  return size;
}

size_t release_kept_blocks() {
  size_t bytes = 0;
  for (const auto& [p, n] : BlockCache::get().take_all()) {
#if defined(__linux__)
    (void)munmap(p, n);
#endif
    bytes += n;
  }
  return bytes;
}

SystemBlock::SystemBlock(size_t bytes) : bytes_(bytes) {
#if defined(__linux__)
  if (bytes <= kCachedBlock) {
    if (void* kept = BlockCache::get().take(bytes)) {
      data_ = static_cast<char*>(kept);
      mapped_ = true;
      return;
    }
  }
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p != MAP_FAILED) {
    advise_huge(p, bytes);
    data_ = static_cast<char*>(p);
    mapped_ = true;
    return;
  }
#endif
  data_ = new char[bytes];
}

SystemBlock::~SystemBlock() {
#if defined(__linux__)
  if (mapped_) {
    if (!BlockCache::get().keep(data_, bytes_)) (void)munmap(data_, bytes_);
    return;
  }
#endif
  delete[] data_;
}

}  // namespace isoform
