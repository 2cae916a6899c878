// One-rings, boundary and non-manifold flags, and k-ring gathering.
#include "vertex_rings.h"

#include <algorithm>
#include <memory>

#include "../fresh_memory.h"

namespace isoform {

namespace {

// Around v, triangle (v, a, b) in its own order meets a, then b: each
// neighbour once per triangle on the edge to it, so once on a boundary
// edge, twice inside, three or more on a non-manifold edge. The ring keeps
// the order of first meeting, which depends on the triangle table alone.

bool degenerate(const int32_t* t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

// The corners (a, b) of each vertex's triangles (those with a repeated
// vertex left out), in triangle order, one vertex's after another: a count,
// a prefix sum, and a pass that writes each vertex's pairs, moving its
// offset to the next vertex's (offsets end up shifted by one vertex).
// Offset is uint32_t where the pairs allow it, else uint64_t.
template <class Offset>
std::unique_ptr<int32_t[]> corner_pairs(const Mesh& mesh, std::unique_ptr<Offset[]>& at) {
  const size_t n = mesh.vertex_count(), m = mesh.triangle_count();
  const int32_t* tris = mesh.triangles.data();
  at = fresh_array<Offset>(n + 1, false, true);
  std::fill(at.get(), at.get() + n + 1, Offset(0));
  for (size_t t = 0; t < m; ++t) {
    const int32_t* tri = tris + 3 * t;
    if (degenerate(tri)) continue;
    for (int i = 0; i < 3; ++i) ++at[size_t(tri[i]) + 1];
  }
  for (size_t v = 0; v < n; ++v) at[v + 1] += at[v];
  // Fresh pages, in 2 MB pages where the system allows (fresh_memory.h).
  std::unique_ptr<int32_t[]> pairs = fresh_array<int32_t>(2 * size_t(at[n]), false, true);
  for (size_t t = 0; t < m; ++t) {
    const int32_t* tri = tris + 3 * t;
    if (degenerate(tri)) continue;
    // At corner i the other two corners in the triangle's order: i + 1,
    // then i + 2 (mod 3).
    const int32_t a = tri[0], b = tri[1], c = tri[2];
    int32_t* pair = pairs.get() + 2 * size_t(at[size_t(a)]++);
    pair[0] = b;
    pair[1] = c;
    pair = pairs.get() + 2 * size_t(at[size_t(b)]++);
    pair[0] = c;
    pair[1] = a;
    pair = pairs.get() + 2 * size_t(at[size_t(c)]++);
    pair[0] = a;
    pair[1] = b;
  }
  return pairs;
}

}  // namespace

VertexRings::VertexRings(const Mesh& mesh) {
  const size_t m = mesh.triangle_count();
  if (3 * m < size_t(UINT32_MAX))
    build<uint32_t>(mesh);
  else
    build<uint64_t>(mesh);
}

template <class Offset>
void VertexRings::build(const Mesh& mesh) {
  const size_t n = mesh.vertex_count();
  std::unique_ptr<Offset[]> at;
  std::unique_ptr<int32_t[]> pairs = corner_pairs(mesh, at);
  // Vertex v's pairs are [at[v - 1], at[v]) now (at[-1] = 0). Around v
  // each neighbour w is counted in one mark per vertex: (v + 1) * 4 plus
  // how often w was met around v (1, 2, or 3 for three or more), so a mark
  // from another vertex reads as not met yet. Marks are 32 bits where the
  // tags fit, else 64. The rings take the pairs' place: a vertex's ring
  // is no longer than its pairs and starts no later, so it is written over
  // pairs already read.
  ring_ = std::move(pairs);
  if (n < (size_t(1) << 30) - 1)
    rings_from_pairs<uint32_t>(at.get(), n);
  else
    rings_from_pairs<uint64_t>(at.get(), n);
}

template <class Mark, class Offset>
void VertexRings::rings_from_pairs(const Offset* at, size_t n) {
  fresh_resize(start_, n + 1, false, true);
  fresh_resize(boundary_, n, false, true);
  fresh_resize(nonmanifold_, n, false, true);
  int32_t* const out = ring_.get();
  std::unique_ptr<Mark[]> mark = fresh_array<Mark>(n, false, true);
  std::fill(mark.get(), mark.get() + n, Mark(0));
  size_t size = 0;
  for (size_t v = 0; v < n; ++v) {
    const Mark tag = Mark(v + 1) << 2;
    const size_t from = v ? size_t(at[v - 1]) : 0, tris_at = size_t(at[v]) - from;
    const int32_t* e = out + 2 * from;  // entry k is read before out[size <= 2 from + k] is written
    const size_t first = size;
    int64_t boundary_edges = 0;
    // Each entry is written at the end and kept only where new; its count
    // starts at 1 or goes up by one (to at most 3).
    for (size_t k = 0; k < 2 * tris_at; ++k) {
      const int32_t w = e[k];
      const Mark m = mark[size_t(w)], count = m & 3;
      const bool fresh = (m & ~Mark(3)) != tag;
      mark[size_t(w)] = tag | (fresh ? Mark(1) : count + (count < 3));
      out[size] = w;
      size += fresh;
    }
    bool thrice = false;
    for (size_t k = first; k != size; ++k) {
      const Mark u = mark[size_t(out[k])] & 3;
      boundary_edges += u == 1;
      thrice |= u > 2;
    }
    nonmanifold_[v] = thrice;
    const size_t distinct = size - first;
    // A single closed fan has as many neighbours as triangles; a single open
    // fan one more, with two boundary edges.
    if (boundary_edges > 0) boundary_[v] = 1;
    if (tris_at > 0 && !(boundary_edges == 0 && distinct == tris_at) &&
        !(boundary_edges == 2 && distinct == tris_at + 1))
      nonmanifold_[v] = 1;
    start_[v + 1] = int64_t(size);
    max_valence_ = std::max(max_valence_, distinct);
  }
}

void gather_rings(const VertexRings& rings, int32_t v, int count, RingScratch& s) {
  if (count == 1) {  // the one-ring itself: no search
    s.out.assign(rings.ring_begin(v), rings.ring_end(v));
    return;
  }
  if (s.mark.size() != rings.vertex_count()) {
    s.mark.clear();
    s.mark.shrink_to_fit();
    fresh_resize(s.mark, rings.vertex_count(), false, true);
    s.stamp = 0;
  }
  if (++s.stamp == 0) {  // wrapped: clear the stamps once in 2^32 gathers
    std::fill(s.mark.begin(), s.mark.end(), 0);
    s.stamp = 1;
  }
  const uint32_t stamp = s.stamp;
  uint32_t* mark = s.mark.data();
  if (count <= 0) {
    s.out.clear();
    return;
  }
  mark[size_t(v)] = stamp;
  // Ring r + 1 is what the vertices of ring r (out[from, to)) reach first.
  // Each neighbour is written at the end and kept only when new (no branch
  // on whether it is: which is as good as random). Room for a whole ring's
  // candidates (its vertices' one-rings) is made before it: as many as the
  // largest valence each, or, where that bound is large, their count.
  size_t size = 0;
  int32_t* out = nullptr;
  auto make_room = [&](size_t more) {
    if (s.out.size() < size + more) s.out.resize(2 * (size + more));
    out = s.out.data();
  };
  auto meet_all = [&](const int32_t* w, const int32_t* end) {
    for (; w != end; ++w) {
      const int32_t x = *w;
      const bool fresh = mark[size_t(x)] != stamp;
      mark[size_t(x)] = stamp;
      out[size] = x;
      size += fresh;
    }
  };
  make_room(rings.valence(v));
  meet_all(rings.ring_begin(v), rings.ring_end(v));
  size_t from = 0;
  for (int r = 1; r < count; ++r) {
    const size_t to = size;
    if (to == from) break;
    size_t candidates = (to - from) * rings.max_valence();
    if (candidates > (size_t(1) << 16)) {
      candidates = 0;
      for (size_t i = from; i < to; ++i) candidates += rings.valence(out[i]);
    }
    make_room(candidates);
    for (size_t i = from; i < to; ++i) {
      const int32_t u = out[i];
      meet_all(rings.ring_begin(u), rings.ring_end(u));
    }
    from = to;
  }
  s.out.resize(size);
}

}  // namespace isoform
