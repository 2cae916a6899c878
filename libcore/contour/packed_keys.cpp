// Packing shared-vertex keys: the extent of the keys' coordinates.
#include "packed_keys.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace isoform {
namespace {

struct Extent {
  uint64_t lo[3] = {~uint64_t(0), ~uint64_t(0), ~uint64_t(0)}, hi[3] = {0, 0, 0};
  void add(uint64_t key) {
    const uint64_t c[3] = {key >> 43, (key >> 23) & 0xFFFFF, (key >> 3) & 0xFFFFF};
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], c[a]);
      hi[a] = std::max(hi[a], c[a]);
    }
  }
};

// Bits needed for the values 0 .. n.
int bits_for(uint64_t n) { return n == 0 ? 0 : 64 - __builtin_clzll(n); }

}  // namespace

PackedLayout packed_layout(const std::vector<BrickMesh>& bricks, size_t vertex_count) {
  tbb::enumerable_thread_specific<Extent> extents;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, bricks.size(), 4), [&](const tbb::blocked_range<size_t>& r) {
    Extent& e = extents.local();
    for (size_t b = r.begin(); b != r.end(); ++b)
      for (size_t m = 0; m < bricks[b].shared_count; ++m) e.add(bricks[b].shared[m].first);
  });
  Extent all;
  bool any = false;
  for (const Extent& e : extents)
    for (int a = 0; a < 3; ++a) {
      any |= e.hi[a] >= e.lo[a];
      all.lo[a] = std::min(all.lo[a], e.lo[a]);
      all.hi[a] = std::max(all.hi[a], e.hi[a]);
    }
  PackedLayout layout;
  if (!any) return layout;  // no keys: the pairs' path handles the empty sort
  layout.vertex_bits = bits_for(vertex_count > 0 ? uint64_t(vertex_count - 1) : 0);
  int at = layout.vertex_bits + 3;  // the slot sits above the vertex
  for (int a = 2; a >= 0; --a) {
    const int bits = bits_for(all.hi[a] - all.lo[a]);
    layout.low[a] = all.lo[a];
    layout.shift[a] = bits > 0 ? at : 0;  // a constant coordinate packs as 0
    at += bits;
  }
  layout.bits = at;
  layout.fits = at <= 64;
  return layout;
}

}  // namespace isoform
