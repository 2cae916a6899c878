// The vertex-to-triangle table (see vertex_stars.h).
#include "vertex_stars.h"

#include <algorithm>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace isoform {

// NOTE: a counting sort in a few stretches of triangles side by side, each
// with its own counts per vertex; a vertex's list then holds the first
// stretch's triangles, then the second's, and so on: ascending, as one scan
// of the triangles would list them.
VertexStars vertex_stars(const Mesh& mesh) {
  const size_t nv = mesh.vertex_count(), nt = mesh.triangle_count();
  const size_t stretches = nt < 65536 ? 1 : size_t(std::clamp(tbb::this_task_arena::max_concurrency(), 1, 4));
  const size_t per = (nt + stretches - 1) / std::max<size_t>(stretches, 1);
  std::vector<std::vector<int64_t>> fill(stretches, std::vector<int64_t>(nv, 0));
  const auto each_stretch = [&](auto visit) {
    tbb::parallel_for(size_t(0), stretches, [&](size_t s) {
      const size_t last = std::min(nt, (s + 1) * per);
      for (size_t t = s * per; t < last; ++t)
        for (int k = 0; k < 3; ++k) visit(fill[s], t, size_t(mesh.triangles[3 * t + size_t(k)]));
    });
  };
  each_stretch([](std::vector<int64_t>& count, size_t, size_t v) { ++count[v]; });
  VertexStars stars;
  stars.start.assign(nv + 1, 0);
  for (size_t v = 0; v < nv; ++v) {
    int64_t at = stars.start[v];
    for (size_t s = 0; s < stretches; ++s) {
      const int64_t count = fill[s][v];
      fill[s][v] = at;
      at += count;
    }
    stars.start[v + 1] = at;
  }
  stars.faces.resize(3 * nt);
  each_stretch([&](std::vector<int64_t>& next, size_t t, size_t v) { stars.faces[size_t(next[v]++)] = int32_t(t); });
  return stars;
}

}  // namespace isoform
