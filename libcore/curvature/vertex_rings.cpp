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
  // boundary edge, twice inside, three or more on a non-manifold edge.
  start_.assign(n + 1, 0);
  boundary_.assign(n, 0);
  nonmanifold_.assign(n, 0);
  ring_.reserve(all.size() / 2 + n);
  for (size_t v = 0; v < n; ++v) {
    auto b = all.begin() + start[v], e = all.begin() + start[v + 1];
    std::sort(b, e);
    int64_t distinct = 0, boundary_edges = 0;
    for (auto it = b; it != e;) {
      auto run = std::upper_bound(it, e, *it);
      const auto uses = run - it;
      if (uses == 1) ++boundary_edges;
      if (uses > 2) nonmanifold_[v] = 1;
      ring_.push_back(*it);
      ++distinct;
      it = run;
    }
    // A single closed fan has as many neighbours as triangles; a single open
    // fan one more, with two boundary edges.
    const int64_t tris = triangles_at[v];
    if (boundary_edges > 0) boundary_[v] = 1;
    if (tris > 0 && !(boundary_edges == 0 && distinct == tris) && !(boundary_edges == 2 && distinct == tris + 1))
      nonmanifold_[v] = 1;
    start_[v + 1] = int64_t(ring_.size());
  }
}

void gather_rings(const VertexRings& rings, int32_t v, int count, RingScratch& s) {
  if (s.mark.size() != rings.vertex_count()) {
    s.mark.assign(rings.vertex_count(), 0);
    s.stamp = 0;
  }
  if (++s.stamp == 0) {  // wrapped: clear the stamps once in 2^32 gathers
    std::fill(s.mark.begin(), s.mark.end(), 0);
    s.stamp = 1;
  }
  s.out.clear();
  s.mark[size_t(v)] = s.stamp;
  s.seeds.assign(1, v);
  for (int r = 0; r < count; ++r) {
    const size_t ring_start = s.out.size();
    for (int32_t u : s.seeds)
      for (const int32_t* w = rings.ring_begin(u); w != rings.ring_end(u); ++w)
        if (s.mark[size_t(*w)] != s.stamp) {
          s.mark[size_t(*w)] = s.stamp;
          s.out.push_back(*w);
        }
    std::sort(s.out.begin() + long(ring_start), s.out.end());
    if (s.out.size() == ring_start) break;
    s.seeds.assign(s.out.begin() + long(ring_start), s.out.end());
  }
}

}  // namespace isoform
