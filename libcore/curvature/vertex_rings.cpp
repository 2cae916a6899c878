// One-rings, boundary and non-manifold flags, and k-ring gathering.
#include "vertex_rings.h"

#include <algorithm>
#include <numeric>

namespace isoform {

VertexRings::VertexRings(const Mesh& mesh) {
  const size_t n = mesh.vertex_count(), m = mesh.triangle_count();
  std::vector<int64_t> start(n + 1, 0), triangles_at(n, 0);
  for (size_t t = 0; t < m; ++t) {
    const int32_t* tri = &mesh.triangles[3 * t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
    for (int i = 0; i < 3; ++i) {
      start[size_t(tri[i]) + 1] += 2;
      ++triangles_at[size_t(tri[i])];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int32_t> all(static_cast<size_t>(start[n]));
  std::vector<int64_t> fill(start.begin(), start.end() - 1);
  for (size_t t = 0; t < m; ++t) {
    const int32_t* tri = &mesh.triangles[3 * t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
    for (int i = 0; i < 3; ++i) {
      all[size_t(fill[size_t(tri[i])]++)] = tri[(i + 1) % 3];
      all[size_t(fill[size_t(tri[i])]++)] = tri[(i + 2) % 3];
    }
  }
  // Each neighbour appears once per triangle on the edge to it: once on a
  // boundary edge, twice inside, three or more on a non-manifold edge. The
  // uses are counted in per-vertex stamps (seen[w] == v + 1: w already met
  // around v), in one pass and without sorting; the ring keeps the order of
  // first meeting, which depends on the triangle table alone.
  start_.assign(n + 1, 0);
  boundary_.assign(n, 0);
  nonmanifold_.assign(n, 0);
  ring_.resize(all.size() / 2 + n);
  std::vector<int32_t> seen(n, 0);
  std::vector<uint8_t> uses(n, 0);
  int64_t size = 0;
  for (size_t v = 0; v < n; ++v) {
    const int32_t tag = int32_t(v) + 1;
    const int64_t first = size;
    for (int64_t k = start[v]; k != start[v + 1]; ++k) {
      const int32_t w = all[size_t(k)];
      if (seen[size_t(w)] != tag) {
        seen[size_t(w)] = tag;
        uses[size_t(w)] = 1;
        if (size_t(size) == ring_.size()) ring_.resize(ring_.size() * 2 + 16);
        ring_[size_t(size++)] = w;
      } else if (uses[size_t(w)] < 255) {
        ++uses[size_t(w)];
      }
    }
    int64_t boundary_edges = 0;
    for (int64_t k = first; k != size; ++k) {
      const uint8_t u = uses[size_t(ring_[size_t(k)])];
      boundary_edges += u == 1;
      if (u > 2) nonmanifold_[v] = 1;
    }
    const int64_t distinct = size - first;
    // A single closed fan has as many neighbours as triangles; a single open
    // fan one more, with two boundary edges.
    const int64_t tris = triangles_at[v];
    if (boundary_edges > 0) boundary_[v] = 1;
    if (tris > 0 && !(boundary_edges == 0 && distinct == tris) && !(boundary_edges == 2 && distinct == tris + 1))
      nonmanifold_[v] = 1;
    start_[v + 1] = size;
  }
  ring_.resize(size_t(size));
}

void gather_rings(const VertexRings& rings, int32_t v, int count, RingScratch& s) {
  if (count == 1) {  // the one-ring itself: no search
    s.out.assign(rings.ring_begin(v), rings.ring_end(v));
    return;
  }
  if (s.mark.size() != rings.vertex_count()) {
    s.mark.assign(rings.vertex_count(), 0);
    s.stamp = 0;
  }
  if (++s.stamp == 0) {  // wrapped: clear the stamps once in 2^32 gathers
    std::fill(s.mark.begin(), s.mark.end(), 0);
    s.stamp = 1;
  }
  const uint32_t stamp = s.stamp;
  uint32_t* mark = s.mark.data();
  s.out.clear();
  if (count <= 0) return;
  mark[size_t(v)] = stamp;
  // Ring r + 1 is what the vertices of ring r (out[from, to)) reach first.
  const int32_t* first = rings.ring_begin(v);
  for (const int32_t* w = first; w != rings.ring_end(v); ++w)
    if (mark[size_t(*w)] != stamp) {
      mark[size_t(*w)] = stamp;
      s.out.push_back(*w);
    }
  size_t from = 0;
  for (int r = 1; r < count; ++r) {
    const size_t to = s.out.size();
    if (to == from) break;
    for (size_t i = from; i < to; ++i) {
      const int32_t u = s.out[i];
      for (const int32_t* w = rings.ring_begin(u); w != rings.ring_end(u); ++w)
        if (mark[size_t(*w)] != stamp) {
          mark[size_t(*w)] = stamp;
          s.out.push_back(*w);
        }
    }
    from = to;
  }
}

}  // namespace isoform
