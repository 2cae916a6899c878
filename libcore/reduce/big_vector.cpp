// The reduction's large arrays on 2 MB pages (see big_vector.h).
#include "big_vector.h"

#include <cstdint>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace isoform::reduce {
namespace {

size_t rounded(size_t bytes) { return (bytes + kBigBytes - 1) / kBigBytes * kBigBytes; }

}  // namespace

#if defined(__linux__)

// Maps one page more than needed and gives back what lies before the first
// 2 MB boundary and after the array's last page.
void* allocate_big(size_t bytes) {
  const size_t size = rounded(bytes);
  void* raw = mmap(nullptr, size + kBigBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const uintptr_t first = uintptr_t(raw), start = (first + kBigBytes - 1) / kBigBytes * kBigBytes;
  const size_t head = start - first, tail = kBigBytes - head;
  if (head > 0) munmap(raw, head);
  if (tail > 0) munmap(reinterpret_cast<void*>(start + size), tail);
  madvise(reinterpret_cast<void*>(start), size, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(start);
}

void free_big(void* p, size_t bytes) { munmap(p, rounded(bytes)); }

#else

void* allocate_big(size_t bytes) { return ::operator new(bytes); }
void free_big(void* p, size_t) { ::operator delete(p); }

#endif

}  // namespace isoform::reduce
