// One-rings, boundary and non-manifold flags, and k-ring gathering.
#include "vertex_rings.h"

#include <algorithm>
#include <memory>

#if defined(__x86_64__) && defined(__GNUC__)
// GCC 12's headers make their "undefined" vectors by self-initialisation,
// which -Wmaybe-uninitialized reports wherever they are inlined.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#endif

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

VertexRings::VertexRings(const Mesh& mesh, bool vector_instructions) {
  const size_t m = mesh.triangle_count();
  if (3 * m < size_t(UINT32_MAX))
    build<uint32_t>(mesh, vector_instructions);
  else
    build<uint64_t>(mesh, vector_instructions);
}

template <class Offset>
void VertexRings::build(const Mesh& mesh, bool vector_instructions) {
  const size_t n = mesh.vertex_count();
  std::unique_ptr<Offset[]> at;
  std::unique_ptr<int32_t[]> pairs = corner_pairs(mesh, at);
  // Vertex v's pairs are [at[v - 1], at[v]) now (at[-1] = 0). Each
  // vertex's neighbours are found by conflict detection or counted in marks
  // (ring_by_marks); marks are 32 bits where their tags fit, else 64. The
  // rings take the pairs' place: a vertex's ring is no longer than its
  // pairs and starts no later, so it is written over pairs already read.
  ring_ = std::move(pairs);
  if (n < (size_t(1) << 30) - 1)
    rings_from_pairs<uint32_t>(at.get(), n, vector_instructions);
  else
    rings_from_pairs<uint64_t>(at.get(), n, vector_instructions);
}

namespace {

#define ISOFORM_RING_INLINE inline __attribute__((always_inline))

// One vertex's ring from its corner pairs e[0, count): the neighbours in
// the order of first meeting written to out (which may lie over e: nothing
// of e is read after out passes it), with how many of them are met once (a
// boundary edge) and whether one is met three times or more.
struct RingOfVertex {
  size_t distinct = 0;
  int64_t single = 0;
  bool thrice = false;
};

// With one mark per vertex: (v + 1) * 4 plus how often w was met around v
// (1, 2, or 3 for three or more), so a mark from another vertex reads as
// not met yet. Each entry is written at the end and kept only where new;
// its count starts at 1 or goes up by one (to at most 3).
template <class Mark>
RingOfVertex ring_by_marks(const int32_t* e, size_t count, Mark tag, Mark* mark, int32_t* out) {
  RingOfVertex r;
  for (size_t k = 0; k < count; ++k) {
    const int32_t w = e[k];
    const Mark m = mark[size_t(w)], c = m & 3;
    const bool fresh = (m & ~Mark(3)) != tag;
    mark[size_t(w)] = tag | (fresh ? Mark(1) : c + (c < 3));
    out[r.distinct] = w;
    r.distinct += fresh;
  }
  for (size_t k = 0; k != r.distinct; ++k) {
    const Mark u = mark[size_t(out[k])] & 3;
    r.single += u == 1;
    r.thrice |= u > 2;
  }
  return r;
}

#if defined(__x86_64__) && defined(__GNUC__)
#define ISOFORM_RING_CONFLICT 1
#define ISOFORM_CONFLICT_TARGET __attribute__((target("avx512f,avx512cd")))

// Up to 16 entries at once by AVX-512 conflict detection: for each entry a
// bit per earlier entry equal to it. An entry without one is the first
// meeting; one with two or more is a third meeting; an entry that a later
// one names is met again. No memory but e and out, so no chain through
// the marks from one entry to the next.
ISOFORM_CONFLICT_TARGET inline RingOfVertex ring_by_conflicts(const int32_t* e, size_t count, int32_t* out) {
  const __mmask16 valid = __mmask16((1u << count) - 1);
  const __m512i w = _mm512_maskz_loadu_epi32(valid, e);
  const __m512i earlier = _mm512_maskz_conflict_epi32(valid, w);
  const __mmask16 first = _mm512_mask_testn_epi32_mask(valid, earlier, earlier);
  const __m512i fewer = _mm512_sub_epi32(earlier, _mm512_set1_epi32(1));
  const unsigned again = _mm512_reduce_or_epi32(earlier);
  RingOfVertex r;
  r.thrice = _mm512_mask_test_epi32_mask(valid, earlier, fewer) != 0;  // two bits or more
  r.distinct = size_t(__builtin_popcount(first));
  r.single = __builtin_popcount(first & ~again);
  // The first meetings packed in order, stored where valid only.
  const __m512i packed = _mm512_maskz_compress_epi32(first, w);
  _mm512_mask_storeu_epi32(out, __mmask16((1u << r.distinct) - 1), packed);
  return r;
}

bool has_conflict_detection() {
  static const bool yes = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd");
  return yes;
}
#endif

// Each vertex's ring over its pairs (Ring: which way a vertex's ring is
// found, given its pairs, their count and where to write), its flags, and
// the offsets.
template <class Offset, class Ring>
ISOFORM_RING_INLINE size_t rings_pass(const Offset* at, size_t n, int32_t* out, int64_t* start, uint8_t* boundary,
                                      uint8_t* nonmanifold, Ring ring) {
  size_t size = 0, most = 0;
  for (size_t v = 0; v < n; ++v) {
    const size_t from = v ? size_t(at[v - 1]) : 0, tris_at = size_t(at[v]) - from;
    // entry k is read before out[size <= 2 from + k] is written
    const RingOfVertex r = ring(v, out + 2 * from, 2 * tris_at, out + size);
    size += r.distinct;
    // A single closed fan has as many neighbours as triangles; a single open
    // fan one more, with two boundary edges.
    boundary[v] = r.single > 0;
    nonmanifold[v] = r.thrice || (tris_at > 0 && !(r.single == 0 && r.distinct == tris_at) &&
                                  !(r.single == 2 && r.distinct == tris_at + 1));
    start[v + 1] = int64_t(size);
    most = std::max(most, r.distinct);
  }
  return most;
}

#ifdef ISOFORM_RING_CONFLICT
// Conflict detection where the pairs fit one vector, the fallback (the
// marks) elsewhere.
template <class Fallback>
struct ByConflicts {
  Fallback& fallback;
  ISOFORM_CONFLICT_TARGET RingOfVertex operator()(size_t v, const int32_t* e, size_t count, int32_t* out) const {
    if (count <= 16) return ring_by_conflicts(e, count, out);
    return fallback(v, e, count, out);
  }
};

template <class Offset, class Fallback>
ISOFORM_CONFLICT_TARGET size_t rings_pass_conflicts(const Offset* at, size_t n, int32_t* out, int64_t* start,
                                                    uint8_t* boundary, uint8_t* nonmanifold, Fallback& fallback) {
  return rings_pass(at, n, out, start, boundary, nonmanifold, ByConflicts<Fallback>{fallback});
}
#endif

}  // namespace

template <class Mark, class Offset>
void VertexRings::rings_from_pairs(const Offset* at, size_t n, bool vector_instructions) {
  fresh_resize(start_, n + 1, false, true);
  fresh_resize(boundary_, n, false, true);
  fresh_resize(nonmanifold_, n, false, true);
  int32_t* const ring = ring_.get();
  // The marks, made when a vertex first needs them.
  std::unique_ptr<Mark[]> mark;
  auto by_marks = [&](size_t v, const int32_t* e, size_t count, int32_t* out) {
    if (!mark) {
      mark = fresh_array<Mark>(n, false, true);
      std::fill(mark.get(), mark.get() + n, Mark(0));
    }
    return ring_by_marks<Mark>(e, count, Mark(v + 1) << 2, mark.get(), out);
  };
#ifdef ISOFORM_RING_CONFLICT
  if (vector_instructions && has_conflict_detection()) {
    max_valence_ = rings_pass_conflicts(at, n, ring, start_.data(), boundary_.data(), nonmanifold_.data(), by_marks);
    return;
  }
#endif
  max_valence_ = rings_pass(at, n, ring, start_.data(), boundary_.data(), nonmanifold_.data(), by_marks);
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
