// Sample blocks for the curvature of trivariate graphs.
#include "graph_block.h"

#include <algorithm>

namespace isoform {

void GraphBlock::reset(const Index3& first, const Index3& count) {
  first_ = first;
  count_ = count;
  for (int a = 0; a < 3; ++a) {
    lo_[a] = first[a] - kGraphReach;
    dims_[a] = count[a] + 2 * kGraphReach;
  }
  const size_t n = size_t(dims_[0]) * size_t(dims_[1]) * size_t(dims_[2]);
  values_.assign(n, 0.0);
  defined_.assign(n, 0);
}

GraphSamples GraphBlock::samples(const Index3& p) const {
  GraphSamples s;
  const size_t at = index(p);
  s.values = values_.data() + at;
  s.defined = defined_.data() + at;
  s.stride[0] = 1;
  s.stride[1] = dims_[0];
  s.stride[2] = std::ptrdiff_t(dims_[0]) * dims_[1];
  return s;
}

// Brick-relative samples [from, cells + to_extra) per axis.
void GraphBlock::add_range(const Brick& brick, int from, int to_extra) {
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::max(from, lo_[a] - brick.origin[a]);
    hi[a] = std::min(brick.cells[a] + to_extra, lo_[a] + dims_[a] - brick.origin[a]);
    if (lo[a] >= hi[a]) return;
  }
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i)
        if (brick.is_defined(i, j, k))
          set({brick.origin[0] + i, brick.origin[1] + j, brick.origin[2] + k}, double(brick.value(i, j, k)));
}

void GraphBlock::add_brick(const Brick& brick) { add_range(brick, -1, 2); }
void GraphBlock::add_brick_own(const Brick& brick) { add_range(brick, 0, 0); }

}  // namespace isoform
