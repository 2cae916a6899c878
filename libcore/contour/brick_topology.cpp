// Neighbours and parts inside one brick (Hamann 1991, Algorithms 3.1, 3.2).
#include "brick_topology.h"

#include <algorithm>

namespace isoform {
namespace {

int corner_of(const int32_t* tri, int32_t v) { return tri[0] == v ? 0 : tri[1] == v ? 1 : tri[2] == v ? 2 : -1; }

}  // namespace

void BrickTopology::vertex_triangles(const int32_t* tris, size_t nt, size_t nv) {
  // Counts, then inclusive sums (start_[v] = end of v's run), then a fill
  // from the back that moves each start_[v] down to the beginning of its run.
  start_.assign(nv + 1, 0);
  for (size_t c = 0; c < 3 * nt; ++c) ++start_[size_t(tris[c])];
  for (size_t v = 1; v < nv; ++v) start_[v] += start_[v - 1];
  start_[nv] = int32_t(3 * nt);
  around_.resize(3 * nt);
  for (size_t c = 3 * nt; c-- > 0;) around_[size_t(--start_[size_t(tris[c])])] = int32_t(c / 3);
}

int32_t BrickTopology::run(const int32_t* tris, size_t nt, size_t nv, const uint8_t* shared,
                           const int32_t* final_vertex, int64_t first_triangle, int32_t* neighbours,
                           int32_t* parts, TopologyCounts& counts, std::vector<SeamEdge>& seams) {
  vertex_triangles(tris, nt, nv);
  root_.resize(nt);
  for (size_t t = 0; t < nt; ++t) root_[t] = int32_t(t);
  auto find = [&](int32_t x) {
    while (root_[size_t(x)] != x) x = root_[size_t(x)] = root_[size_t(root_[size_t(x)])];
    return x;
  };
  for (size_t t = 0; t < nt; ++t) {
    const int32_t* tri = &tris[3 * t];
    for (int i = 0; i < 3; ++i) {
      const int32_t a = tri[i], b = tri[(i + 1) % 3];
      const size_t at = 3 * t + size_t(i);
      if (shared[a] && shared[b]) {
        const uint64_t fa = uint64_t(final_vertex[a]), fb = uint64_t(final_vertex[b]);
        seams.push_back({fa < fb ? (fa << 32) | fb : (fb << 32) | fa, uint64_t(3 * first_triangle) + at});
        continue;
      }
      // As compute_neighbours: every triangle around a that holds b.
      int count = 0;
      int32_t other = -1;
      bool same_direction = false, lowest = true;
      for (int32_t s = start_[size_t(a)]; s < start_[size_t(a) + 1]; ++s) {
        const int32_t u = around_[size_t(s)];
        if (size_t(u) == t) continue;
        const int32_t* ut = &tris[3 * size_t(u)];
        const int cb = corner_of(ut, b);
        if (cb < 0) continue;
        ++count;
        other = u;
        if (size_t(u) < t) lowest = false;
        if (ut[(cb + 2) % 3] == a) same_direction = true;
      }
      counts.edges += lowest;
      neighbours[at] = -1;
      if (count == 0) {
        ++counts.boundary;
      } else if (count == 1) {
        neighbours[at] = int32_t(first_triangle + other);
        if (same_direction && size_t(other) > t) ++counts.inconsistent;
        const int32_t ra = find(int32_t(t)), rb = find(other);
        if (ra != rb) root_[size_t(std::max(ra, rb))] = std::min(ra, rb);
      } else if (lowest) {
        ++counts.nonmanifold;
      }
    }
  }
  // Roots are the smallest triangle of their part: number them in order.
  int32_t next = 0;
  for (size_t t = 0; t < nt; ++t) {
    const int32_t r = find(int32_t(t));
    parts[t] = size_t(r) == t ? next++ : parts[size_t(r)];
  }
  return next;
}

}  // namespace isoform
