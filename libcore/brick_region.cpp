// BrickSource::fill_region's default: a dense box gathered from the bricks.
#include <algorithm>

#include "volume.h"

namespace isoform {

void BrickSource::fill_region(const Index3& lo, const Index3& dims, float outside,
                              std::vector<float>& out) const {
  out.assign(size_t(dims[0]) * size_t(dims[1]) * size_t(dims[2]), outside);
  Brick brick;
  for (size_t b = 0; b < brick_count(); ++b) {
    fill(b, brick);
    // The brick holds the corners origin .. origin + cells of its cells.
    Index3 from, to;
    for (int a = 0; a < 3; ++a) {
      from[a] = std::max(brick.origin[a], lo[a]);
      to[a] = std::min(brick.origin[a] + brick.cells[a], lo[a] + dims[a] - 1);
    }
    if (from[0] > to[0] || from[1] > to[1] || from[2] > to[2]) continue;
    for (int z = from[2]; z <= to[2]; ++z)
      for (int y = from[1]; y <= to[1]; ++y)
        for (int x = from[0]; x <= to[0]; ++x) {
          const int i = x - brick.origin[0], j = y - brick.origin[1], k = z - brick.origin[2];
          if (!brick.is_defined(i, j, k)) continue;
          out[(size_t(z - lo[2]) * size_t(dims[1]) + size_t(y - lo[1])) * size_t(dims[0]) +
              size_t(x - lo[0])] = brick.value(i, j, k);
        }
  }
}

}  // namespace isoform
