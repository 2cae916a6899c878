// One-rings, boundary and non-manifold flags, and k-ring gathering.
#include "vertex_rings.h"

#include <algorithm>
#include <memory>
#include <numeric>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace isoform {

namespace {

// The neighbours met around one vertex, for vertices with at most kSlots / 2
// triangles (nearly all): the kSlots entries (a, b of each triangle, the
// rest no vertex) compared all against all, without branches on the data.
// An entry is a neighbour's first meeting where no earlier entry equals it;
// the number of equal entries is how often it is met.
constexpr int kSlots = 16;

struct Fan {
  alignas(16) int32_t entry[kSlots];

  // Entries equal to entry i, as a bit mask over the entries.
  unsigned equal(int i) const {
#if defined(__SSE2__)
    const __m128i x = _mm_set1_epi32(entry[i]);
    unsigned mask = 0;
    for (int j = 0; j < kSlots; j += 4) {
      const __m128i e = _mm_cmpeq_epi32(_mm_load_si128(reinterpret_cast<const __m128i*>(entry + j)), x);
      mask |= unsigned(_mm_movemask_ps(_mm_castsi128_ps(e))) << j;
    }
    return mask;
#else
    unsigned mask = 0;
    for (int j = 0; j < kSlots; ++j) mask |= unsigned(entry[j] == entry[i]) << j;
    return mask;
#endif
  }
};

// The other two corners of triangle tri at the corner holding v, in the
// triangle's order.
inline void others(const int32_t* tri, int32_t v, int32_t& a, int32_t& b) {
  const int i = (tri[1] == v) + 2 * (tri[2] == v);
  static constexpr int next[3] = {1, 2, 0}, prev[3] = {2, 0, 1};
  a = tri[next[i]];
  b = tri[prev[i]];
}

}  // namespace

VertexRings::VertexRings(const Mesh& mesh) {
  const size_t n = mesh.vertex_count(), m = mesh.triangle_count();
  const int32_t* tris = mesh.triangles.data();
  // The triangles at each vertex (those with a repeated vertex left out), in
  // triangle order: a count, a prefix sum, and a pass that fills each
  // vertex's list, moving its start to the next vertex's, shifted back after.
  std::vector<int64_t> at(n + 1, 0);
  auto degenerate = [](const int32_t* t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; };
  for (size_t t = 0; t < m; ++t) {
    const int32_t* tri = tris + 3 * t;
    if (degenerate(tri)) continue;
    for (int i = 0; i < 3; ++i) ++at[size_t(tri[i]) + 1];
  }
  std::partial_sum(at.begin(), at.end(), at.begin());
  std::unique_ptr<int32_t[]> fan(new int32_t[size_t(at[n])]);  // triangle indices; every entry is written
  for (size_t t = 0; t < m; ++t) {
    const int32_t* tri = tris + 3 * t;
    if (degenerate(tri)) continue;
    for (int i = 0; i < 3; ++i) fan[size_t(at[size_t(tri[i])]++)] = int32_t(t);
  }
  for (size_t v = n; v > 0; --v) at[v] = at[v - 1];
  at[0] = 0;
  // Around v, triangle (v, a, b) in its own order meets a, then b: each
  // neighbour once per triangle on the edge to it, so once on a boundary
  // edge, twice inside, three or more on a non-manifold edge. The ring keeps
  // the order of first meeting, which depends on the triangle table alone.
  // Vertices with more triangles than the table takes count in per-vertex
  // stamps instead (seen[w] == v + 1: w already met around v).
  start_.assign(n + 1, 0);
  boundary_.assign(n, 0);
  nonmanifold_.assign(n, 0);
  ring_.resize(size_t(at[n]) + n);
  std::vector<int32_t> seen;
  std::vector<uint8_t> uses;
  int64_t size = 0;
  Fan f;
  for (size_t v = 0; v < n; ++v) {
    const int32_t tag = int32_t(v) + 1;
    const int64_t first = size, tris_at = at[v + 1] - at[v];
    int64_t boundary_edges = 0;
    if (size_t(size) + size_t(2 * tris_at) > ring_.size()) ring_.resize(ring_.size() * 2 + size_t(2 * tris_at));
    if (2 * tris_at <= kSlots) {
      int count = 0;
      for (int64_t k = at[v]; k != at[v + 1]; ++k, count += 2)
        others(tris + 3 * size_t(fan[size_t(k)]), int32_t(v), f.entry[count], f.entry[count + 1]);
      for (int j = count; j < kSlots; ++j) f.entry[j] = -1;
      int32_t* out = ring_.data();
      for (int i = 0; i < count; ++i) {
        const unsigned same = f.equal(i);
        const bool first_meeting = (same & ((1u << i) - 1)) == 0;
        const unsigned but_one = same & (same - 1), but_two = but_one & (but_one - 1);
        out[size] = f.entry[i];
        size += first_meeting;
        boundary_edges += first_meeting & (but_one == 0);   // met once
        nonmanifold_[v] |= uint8_t(first_meeting & (but_two != 0));  // three times or more
      }
    } else {
      if (seen.empty()) {
        seen.assign(n, 0);
        uses.assign(n, 0);
      }
      for (int64_t k = at[v]; k != at[v + 1]; ++k) {
        int32_t ab[2];
        others(tris + 3 * size_t(fan[size_t(k)]), int32_t(v), ab[0], ab[1]);
        for (int32_t w : ab)
          if (seen[size_t(w)] != tag) {
            seen[size_t(w)] = tag;
            uses[size_t(w)] = 1;
            ring_[size_t(size++)] = w;
          } else if (uses[size_t(w)] < 255) {
            ++uses[size_t(w)];
          }
      }
      for (int64_t k = first; k != size; ++k) {
        const uint8_t u = uses[size_t(ring_[size_t(k)])];
        boundary_edges += u == 1;
        if (u > 2) nonmanifold_[v] = 1;
      }
    }
    const int64_t distinct = size - first;
    // A single closed fan has as many neighbours as triangles; a single open
    // fan one more, with two boundary edges.
    if (boundary_edges > 0) boundary_[v] = 1;
    if (tris_at > 0 && !(boundary_edges == 0 && distinct == tris_at) &&
        !(boundary_edges == 2 && distinct == tris_at + 1))
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
  if (count <= 0) {
    s.out.clear();
    return;
  }
  mark[size_t(v)] = stamp;
  // Ring r + 1 is what the vertices of ring r (out[from, to)) reach first.
  // Each neighbour is written at the end and kept only when new (no branch
  // on whether it is: which is as good as random).
  size_t size = 0;
  auto meet_all = [&](const int32_t* w, const int32_t* end) {
    if (s.out.size() < size + size_t(end - w)) s.out.resize(2 * (size + size_t(end - w)));
    int32_t* out = s.out.data();
    for (; w != end; ++w) {
      const bool fresh = mark[size_t(*w)] != stamp;
      mark[size_t(*w)] = stamp;
      out[size] = *w;
      size += fresh;
    }
  };
  meet_all(rings.ring_begin(v), rings.ring_end(v));
  size_t from = 0;
  for (int r = 1; r < count; ++r) {
    const size_t to = size;
    if (to == from) break;
    for (size_t i = from; i < to; ++i) {
      const int32_t u = s.out[i];
      meet_all(rings.ring_begin(u), rings.ring_end(u));
    }
    from = to;
  }
  s.out.resize(size);
}

}  // namespace isoform
