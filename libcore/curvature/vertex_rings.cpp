// One-rings, boundary and non-manifold flags, and k-ring gathering.
#include "vertex_rings.h"

#include <algorithm>
#include <memory>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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
// Offset is uint32_t where the pairs allow it, else uint64_t. The array has
// kSpare entries to spare at its end (read, never used, by the table's
// vector compares).
constexpr size_t kSpare = 16;

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
  std::unique_ptr<int32_t[]> pairs(new int32_t[2 * size_t(at[n]) + kSpare]);
  std::fill(pairs.get() + 2 * size_t(at[n]), pairs.get() + 2 * size_t(at[n]) + kSpare, -1);
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

// The distinct entries of e[0 .. count) (count at most 4 V) in the order of
// their first appearance into out, returning how many; boundary gets how
// many were met once, and the result says whether one was met three times
// or more. e has 4 V entries readable; all compares are against the V
// vectors of entries, held in registers, without branches on the data.
template <int V>
inline int distinct_entries(const int32_t* e, int count, int32_t* out, int64_t& boundary, bool& thrice) {
  const unsigned valid = (1u << count) - 1;
#if defined(__SSE2__)
  __m128i vec[V];
  for (int k = 0; k < V; ++k) vec[k] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(e + 4 * k));
#endif
  int size = 0;
  unsigned many = 0;
  for (int i = 0; i < count; ++i) {
#if defined(__SSE2__)
    const __m128i x = _mm_set1_epi32(e[i]);
    unsigned same = 0;
    for (int k = 0; k < V; ++k)
      same |= unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(vec[k], x)))) << (4 * k);
    same &= valid;
#else
    unsigned same = 0;
    for (int j = 0; j < count; ++j) same |= unsigned(e[j] == e[i]) << j;
#endif
    const bool first_meeting = (same & ((1u << i) - 1)) == 0;
    const unsigned but_one = same & (same - 1), but_two = but_one & (but_one - 1);
    out[size] = e[i];
    size += first_meeting;
    boundary += first_meeting & (but_one == 0);   // met once
    many |= unsigned(first_meeting & (but_two != 0));  // three times or more
  }
  thrice = many != 0;
  return size;
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
  // Vertex v's pairs are [at[v - 1], at[v]) now (at[-1] = 0). Vertices with
  // at most 8 triangles (nearly all) compare their entries all against all
  // (distinct_entries): an entry is a neighbour's first meeting where no
  // earlier entry equals it, and the number of equal entries is how often
  // the neighbour is met. Vertices with more triangles count in
  // per-vertex stamps instead (seen[w] == v + 1: w already met around v).
  start_.resize(n + 1);
  start_[0] = 0;
  boundary_.assign(n, 0);
  nonmanifold_.assign(n, 0);
  capacity_ = size_t(at[n]) + n;
  ring_.reset(new int32_t[capacity_]);
  std::vector<int32_t> seen;
  std::vector<uint8_t> uses;
  size_t size = 0;
  for (size_t v = 0; v < n; ++v) {
    const int32_t tag = int32_t(v) + 1;
    const size_t from = v ? size_t(at[v - 1]) : 0, tris_at = size_t(at[v]) - from;
    const int32_t* e = pairs.get() + 2 * from;
    const size_t first = size;
    int64_t boundary_edges = 0;
    if (size + 2 * tris_at > capacity_) grow(size + 2 * tris_at);
    int32_t* out = ring_.get();
    if (2 * tris_at <= 16) {
      const int count = int(2 * tris_at);
      bool thrice = false;
      switch ((count + 3) / 4) {
        case 0: break;
        case 1: size += size_t(distinct_entries<1>(e, count, out + size, boundary_edges, thrice)); break;
        case 2: size += size_t(distinct_entries<2>(e, count, out + size, boundary_edges, thrice)); break;
        case 3: size += size_t(distinct_entries<3>(e, count, out + size, boundary_edges, thrice)); break;
        default: size += size_t(distinct_entries<4>(e, count, out + size, boundary_edges, thrice)); break;
      }
      nonmanifold_[v] = thrice;
    } else {
      if (seen.empty()) {
        seen.assign(n, 0);
        uses.assign(n, 0);
      }
      for (size_t k = 0; k < 2 * tris_at; ++k) {
        const int32_t w = e[k];
        if (seen[size_t(w)] != tag) {
          seen[size_t(w)] = tag;
          uses[size_t(w)] = 1;
          out[size++] = w;
        } else if (uses[size_t(w)] < 255) {
          ++uses[size_t(w)];
        }
      }
      for (size_t k = first; k != size; ++k) {
        const uint8_t u = uses[size_t(out[k])];
        boundary_edges += u == 1;
        if (u > 2) nonmanifold_[v] = 1;
      }
    }
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
