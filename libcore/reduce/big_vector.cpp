// The reduction's large arrays on 2 MB pages (see big_vector.h).
#include "big_vector.h"

#include <cstdint>
#include <mutex>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace isoform::reduce {

#if defined(__linux__)

namespace {

size_t rounded(size_t bytes) { return (bytes + kBigBytes - 1) / kBigBytes * kBigBytes; }

// The freed arrays' mappings kept for the next arrays (big_vector.h). Made
// once and never destroyed, so that an array freed while the process exits
// still finds it.
class KeptMappings {
 public:
  static KeptMappings& get() {
    static KeptMappings* kept = new KeptMappings;
    return *kept;
  }
  // The smallest kept mapping of at least `size` bytes, cut to `size`, or null.
  void* take(size_t size) {
    std::lock_guard<std::mutex> lock(mutex_);
    size_t best = kept_.size();
    for (size_t i = 0; i < kept_.size(); ++i)
      if (kept_[i].bytes >= size && (best == kept_.size() || kept_[i].bytes < kept_[best].bytes)) best = i;
    if (best == kept_.size()) return nullptr;
    const Mapping m = kept_[best];
    kept_.erase(kept_.begin() + std::ptrdiff_t(best));
    held_ -= m.bytes;
    if (m.bytes > size) munmap(static_cast<char*>(m.start) + size, m.bytes - size);
    return m.start;
  }
  // Keeps the mapping, its pages lazily free, unmapping the oldest kept
  // ones while more than kBigKeptBytes are kept. Where the system cannot
  // mark pages lazily free, the mapping is unmapped at once.
  void keep(void* p, size_t size) {
    if (madvise(p, size, MADV_FREE) != 0) {
      munmap(p, size);
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    kept_.push_back({p, size});
    held_ += size;
    while (held_ > kBigKeptBytes) {
      munmap(kept_.front().start, kept_.front().bytes);
      held_ -= kept_.front().bytes;
      kept_.erase(kept_.begin());
    }
  }
  size_t release() {
    std::lock_guard<std::mutex> lock(mutex_);
    const size_t bytes = held_;
    for (const Mapping& m : kept_) munmap(m.start, m.bytes);
    kept_.clear();
    held_ = 0;
    return bytes;
  }

 private:
  struct Mapping {
    void* start;
    size_t bytes;
  };
  std::mutex mutex_;
  std::vector<Mapping> kept_;  // oldest first
  size_t held_ = 0;
};

}  // namespace

// A kept mapping, else a new one: one page more than needed is mapped, and
// what lies before the first 2 MB boundary and after the array's last page
// is given back.
void* allocate_big(size_t bytes) {
  const size_t size = rounded(bytes);
  if (void* kept = KeptMappings::get().take(size)) return kept;
  void* raw = mmap(nullptr, size + kBigBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const uintptr_t first = uintptr_t(raw), start = (first + kBigBytes - 1) / kBigBytes * kBigBytes;
  const size_t head = start - first, tail = kBigBytes - head;
  if (head > 0) munmap(raw, head);
  if (tail > 0) munmap(reinterpret_cast<void*>(start + size), tail);
  madvise(reinterpret_cast<void*>(start), size, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(start);
}

void free_big(void* p, size_t bytes) { KeptMappings::get().keep(p, rounded(bytes)); }

size_t release_kept_big() { return KeptMappings::get().release(); }

#else

void* allocate_big(size_t bytes) { return ::operator new(bytes); }
void free_big(void* p, size_t) { ::operator delete(p); }
size_t release_kept_big() { return 0; }

#endif

}  // namespace isoform::reduce
