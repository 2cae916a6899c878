// One-rings, boundary and non-manifold flags, and k-ring gathering.
#include "vertex_rings.h"

#include <algorithm>
#include <memory>


namespace isoform {

namespace {

// Around v, triangle (v, a, b) in its own order meets a, then b: each
// neighbour once per triangle on the edge to it, so once on a boundary
// edge, twice inside, three or more on a non-manifold edge. The ring keeps
// the order of first meeting, which depends on the triangle table alone.

// The other two corners of triangle tri at the corner holding v, in the
// triangle's order.
inline void others(const int32_t* tri, int32_t v, int32_t& a, int32_t& b) {
  const int i = (tri[1] == v) + 2 * (tri[2] == v);
  static constexpr int next[3] = {1, 2, 0}, prev[3] = {2, 0, 1};
  a = tri[next[i]];
  b = tri[prev[i]];
}

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
  at.reset(new Offset[n + 1]());
  for (size_t t = 0; t < m; ++t) {
    const int32_t* tri = tris + 3 * t;
    if (degenerate(tri)) continue;
    for (int i = 0; i < 3; ++i) ++at[size_t(tri[i]) + 1];
  }
  for (size_t v = 0; v < n; ++v) at[v + 1] += at[v];
  std::unique_ptr<int32_t[]> pairs(new int32_t[2 * size_t(at[n])]);
  for (size_t t = 0; t < m; ++t) {
    const int32_t* tri = tris + 3 * t;
    if (degenerate(tri)) continue;
    for (int i = 0; i < 3; ++i) {
      int32_t* pair = pairs.get() + 2 * size_t(at[size_t(tri[i])]++);
      others(tri, tri[i], pair[0], pair[1]);
    }
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
  const std::unique_ptr<int32_t[]> pairs = corner_pairs(mesh, at);
  // Vertex v's pairs are [at[v - 1], at[v]) now (at[-1] = 0). Around v
  // each neighbour is counted in per-vertex stamps (seen[w] == v + 1: w
  // already met around v; uses[w]: how often).
  start_.resize(n + 1);
  start_[0] = 0;
  boundary_.assign(n, 0);
  nonmanifold_.assign(n, 0);
  capacity_ = size_t(at[n]) + n;
  ring_.reset(new int32_t[capacity_]);
  std::vector<int32_t> seen(n, 0);
  std::vector<uint8_t> uses(n, 0);
  size_t size = 0;
  for (size_t v = 0; v < n; ++v) {
    const int32_t tag = int32_t(v) + 1;
    const size_t from = v ? size_t(at[v - 1]) : 0, tris_at = size_t(at[v]) - from;
    const int32_t* e = pairs.get() + 2 * from;
    const size_t first = size;
    int64_t boundary_edges = 0;
    if (size + 2 * tris_at > capacity_) grow(size + 2 * tris_at);
    int32_t* out = ring_.get();
    // Each entry is written at the end and kept only where new; its count
    // starts at 1 or goes up by one (to at most 255), without branches on
    // the data.
    for (size_t k = 0; k < 2 * tris_at; ++k) {
      const int32_t w = e[k];
      const bool fresh = seen[size_t(w)] != tag;
      seen[size_t(w)] = tag;
      const uint8_t u = uses[size_t(w)];
      uses[size_t(w)] = fresh ? uint8_t(1) : uint8_t(u + (u < 255));
      out[size] = w;
      size += fresh;
    }
    bool thrice = false;
    for (size_t k = first; k != size; ++k) {
      const uint8_t u = uses[size_t(out[k])];
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

void VertexRings::grow(size_t wanted) {
  const size_t capacity = std::max(wanted, 2 * capacity_);
  std::unique_ptr<int32_t[]> bigger(new int32_t[capacity]);
  std::copy(ring_.get(), ring_.get() + capacity_, bigger.get());
  ring_ = std::move(bigger);
  capacity_ = capacity;
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
