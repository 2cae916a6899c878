// Merging per-brick vertex and triangle tables into one shared-vertex mesh
// with its neighbours and parts.
#include "merge.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>

#include "../errors.h"
#include "brick_topology.h"
#include "../fresh_memory.h"
#include "packed_keys.h"
#include "radix_sort.h"
#include "seams.h"

namespace isoform {
namespace {

// Arrays that are written in full before they are read: no zeroing, pages
// made present up front, in 2 MB pages where the system allows
// (fresh_memory.h: a first touch of a 4 KB page is a fault and a zeroing
// of its own, which costs more than the merge's writes to that page).
template <class T>
std::unique_ptr<T[]> uninitialised(size_t n) {
  return fresh_array<T>(n, true, true);
}

// NOTE: a small grain, so that a grid of a hundred bricks still runs on
// every thread.
template <class F>
void for_each_brick(size_t n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t b = r.begin(); b != r.end(); ++b) f(b);
  });
}

template <class F>
void for_each_index(size_t n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1 << 14), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) f(i);
  });
}

struct Offsets {
  std::vector<size_t> vertex, triangle, shared, seam;  // per brick, exclusive prefix sums
};

Offsets prefix_sums(const std::vector<BrickMesh>& bricks) {
  Offsets o;
  const size_t n = bricks.size();
  o.vertex.resize(n + 1, 0);
  o.triangle.resize(n + 1, 0);
  o.shared.resize(n + 1, 0);
  o.seam.resize(n + 1, 0);
  for (size_t b = 0; b < n; ++b) {
    o.vertex[b + 1] = o.vertex[b] + bricks[b].vertex_count;
    o.triangle[b + 1] = o.triangle[b] + bricks[b].triangle_count;
    o.shared[b + 1] = o.shared[b] + bricks[b].shared_count;
    o.seam[b + 1] = o.seam[b] + bricks[b].seam_count;
  }
  if (o.vertex.back() >= size_t(INT32_MAX) || 3 * o.triangle.back() >= size_t(INT32_MAX))
    throw Unsupported("the contour has more than 2^31 vertices or triangle corners");
  return o;
}

// The final index of every provisional vertex (brick b's local vertex v is
// provisional vertex o.vertex[b] + v). Copies of one edge crossing in
// several bricks (same key) all take the index of the first copy, which
// belongs to the lowest brick; the kept vertices are numbered brick by brick.
struct VertexTable {
  ScratchArray<int32_t> final_index;
  std::vector<int32_t> first;  // per brick: final index of its first kept vertex
};

// The sorted (edge key, provisional vertex) pairs, seen through View:
// same(i, j) when entries i and j hold one key; vertex(i).
template <class View>
void number_vertices(const View& keys, size_t nk, const std::vector<BrickMesh>& bricks, const Offsets& o,
                     VertexTable& vt) {
  const size_t nb = bricks.size();
  int32_t* fin = vt.final_index.get();
  const auto copy = [&](size_t i) { return i > 0 && keys.same(i, i - 1); };
  for_each_index(nk, [&](size_t i) {
    if (copy(i)) fin[keys.vertex(i)] = -1;
  });
  std::vector<int32_t> kept(nb, 0);
  for_each_brick(nb, [&](size_t b) {
    for (size_t v = o.vertex[b]; v < o.vertex[b + 1]; ++v) kept[b] += fin[v] == 0;
  });
  vt.first.resize(nb + 1, 0);
  for (size_t b = 0; b < nb; ++b) vt.first[b + 1] = vt.first[b] + kept[b];
  for_each_brick(nb, [&](size_t b) {
    int32_t next = vt.first[b];
    for (size_t v = o.vertex[b]; v < o.vertex[b + 1]; ++v)
      if (fin[v] == 0) fin[v] = next++;
  });
  for_each_index(nk, [&](size_t i) {
    if (!copy(i)) return;
    size_t head = i - 1;
    while (copy(head)) --head;
    fin[keys.vertex(i)] = fin[keys.vertex(head)];
  });
}

// True when a[0, n) is in increasing order (checked in parallel).
bool sorted(const uint64_t* a, size_t n) {
  std::atomic<bool> ok{true};
  tbb::parallel_for(tbb::blocked_range<size_t>(1, n > 0 ? n : 1, 1 << 16), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i)
      if (a[i - 1] > a[i]) {
        ok = false;
        return;
      }
  });
  return ok;
}

struct PairKeys {
  const std::pair<uint64_t, uint64_t>* k;
  bool same(size_t i, size_t j) const { return k[i].first == k[j].first; }
  size_t vertex(size_t i) const { return size_t(k[i].second); }
};

struct PackedKeys {
  const uint64_t* k;
  int shift;  // bits of the provisional vertex
  bool same(size_t i, size_t j) const { return (k[i] >> shift) == (k[j] >> shift); }
  size_t vertex(size_t i) const { return size_t(k[i] & ((uint64_t(1) << shift) - 1)); }
};

VertexTable vertex_table(const std::vector<BrickMesh>& bricks, const Offsets& o) {
  const size_t nb = bricks.size();
  VertexTable vt;
  vt.final_index = ScratchArray<int32_t>(o.vertex.back());
  int32_t* fin = vt.final_index.get();
  for_each_brick(nb, [&](size_t b) {
    for (size_t v = o.vertex[b]; v < o.vertex[b + 1]; ++v) fin[v] = 0;
  });
  const size_t nk = o.shared.back();
  const PackedLayout layout = packed_layout(bricks, o.vertex.back());
  if (layout.fits) {
    // (edge key, provisional vertex) in one word, in the same order: half
    // the memory of the pairs, and a cheaper sort.
    const ScratchArray<uint64_t> keys(nk);
    for_each_brick(nb, [&](size_t b) {
      size_t at = o.shared[b];
      const BrickMesh& bm = bricks[b];
      for (size_t m = 0; m < bm.shared_count; ++m)
        keys[at++] = layout.pack(bm.shared[m].first, uint64_t(o.vertex[b]) + uint64_t(bm.shared[m].second));
    });
    {
      // The words are distinct (each holds its vertex). They are written
      // with their vertices increasing (bricks in order, each brick's shared
      // vertices in the order it made them), so a stable sort by the bits
      // above the vertex leaves them in the order of the whole words; should
      // they not come out so, a comparison sort puts them there.
      const ScratchArray<uint64_t> buffer(nk);
      radix_sort(keys.get(), buffer.get(), nk, layout.bits, [](uint64_t k) { return k; }, layout.vertex_bits);
    }
    if (!sorted(keys.get(), nk)) tbb::parallel_sort(keys.get(), keys.get() + nk);
    number_vertices(PackedKeys{keys.get(), layout.vertex_bits}, nk, bricks, o, vt);
    return vt;
  }
  using Key = std::pair<uint64_t, uint64_t>;  // (edge key, provisional vertex)
  const std::unique_ptr<Key[]> keys = uninitialised<Key>(nk);
  for_each_brick(nb, [&](size_t b) {
    size_t at = o.shared[b];
    const BrickMesh& bm = bricks[b];
    for (size_t m = 0; m < bm.shared_count; ++m)
      keys[at++] = {bm.shared[m].first, uint64_t(o.vertex[b]) + uint64_t(bm.shared[m].second)};
  });
  tbb::parallel_sort(keys.get(), keys.get() + nk);
  number_vertices(PairKeys{keys.get()}, nk, bricks, o, vt);
  return vt;
}

bool degenerate(const int32_t* tri, const float* vertices) {
  if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) return true;
  const float* p = &vertices[6 * size_t(tri[0])];
  const float* q = &vertices[6 * size_t(tri[1])];
  const float* r = &vertices[6 * size_t(tri[2])];
  const double u[3] = {double(q[0]) - p[0], double(q[1]) - p[1], double(q[2]) - p[2]};
  const double w[3] = {double(r[0]) - p[0], double(r[1]) - p[1], double(r[2]) - p[2]};
  const double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  return c[0] == 0 && c[1] == 0 && c[2] == 0;
}

struct Scratch {
  BrickTopology topology;
  std::vector<uint8_t> shared;
  std::vector<int32_t> triangles;  // reversed brick-local triangles, when asked
  TopologyCounts counts;
  bool missing_normal = false;
};

// The brick's triangles, oriented: its own table, or a reversed copy in out.
const int32_t* oriented_triangles(const BrickMesh& bm, bool reverse, std::vector<int32_t>& out) {
  if (!reverse) return bm.triangles;
  out.assign(bm.triangles, bm.triangles + 3 * size_t(bm.triangle_count));
  for (size_t t = 0; t < bm.triangle_count; ++t) std::swap(out[3 * t + 1], out[3 * t + 2]);
  return out.data();
}

// Brick b's kept vertices and its triangles, written into mesh at the
// brick's offsets.
void place_brick(const BrickMesh& bm, size_t b, const Offsets& o, const VertexTable& vt,
                 const MergeOrientation& orient, Mesh& mesh, Scratch& s) {
  const int32_t* fin = vt.final_index.get() + o.vertex[b];
  const float sign = orient.negate ? -1.0f : 1.0f;
  for (size_t v = 0; v < bm.vertex_count; ++v) {
    const int32_t f = fin[v];
    if (f < vt.first[b] || f >= vt.first[b + 1]) continue;  // another brick's copy
    const float* p = &bm.vertices[6 * v];
    const float* g = p + 3;
    const double len = std::sqrt(double(g[0]) * g[0] + double(g[1]) * g[1] + double(g[2]) * g[2]);
    s.missing_normal |= !(len > 0);
    for (int a = 0; a < 3; ++a) {
      mesh.points[3 * size_t(f) + a] = p[a];
      mesh.normals[3 * size_t(f) + a] = len > 0 ? sign * float(g[a] / len) : 0.0f;
    }
  }
  // Oriented as written: reversed, corners 1 and 2 swap places. Whether a
  // triangle is degenerate does not depend on the order of its corners.
  const int second = orient.reverse ? 2 : 1, third = 3 - second;
  int32_t* out = &mesh.triangles[3 * o.triangle[b]];
  for (size_t t = 0; t < bm.triangle_count; ++t, out += 3) {
    const int32_t* tri = &bm.triangles[3 * t];
    s.counts.degenerate += degenerate(tri, bm.vertices);
    out[0] = fin[tri[0]];
    out[1] = fin[tri[second]];
    out[2] = fin[tri[third]];
  }
}

// Brick b's local neighbours and parts (brick_topology.h).
void brick_topology(const BrickMesh& bm, size_t b, const Offsets& o, const VertexTable& vt,
                    const MergeOrientation& orient, Mesh& mesh, std::vector<int32_t>& part_counts, SeamEdge* seams,
                    Scratch& s) {
  const int32_t* tris = oriented_triangles(bm, orient.reverse, s.triangles);
  const size_t t0 = o.triangle[b];
  if (bm.sides.known) {
    part_counts[b] = s.topology.run_paired(tris, bm.fan_links, orient.reverse, bm.triangle_count, bm.sides,
                                           vt.final_index.get() + o.vertex[b], int64_t(t0), &mesh.neighbours[3 * t0],
                                           &mesh.parts[t0], s.counts, seams + o.seam[b], bm.seam_count);
    return;
  }
  s.shared.assign(bm.vertex_count, 0);
  for (size_t m = 0; m < bm.shared_count; ++m) s.shared[size_t(bm.shared[m].second)] = 1;
  part_counts[b] = s.topology.run(tris, bm.fan_links, orient.reverse, bm.triangle_count, bm.vertex_count,
                                  s.shared.data(), vt.final_index.get() + o.vertex[b], int64_t(t0),
                                  &mesh.neighbours[3 * t0], &mesh.parts[t0], s.counts, seams + o.seam[b],
                                  bm.seam_count);
}

void sum_contour_stats(const std::vector<BrickMesh>& bricks, ContourStats& c) {
  for (const BrickMesh& bm : bricks) {
    c.ambiguous_faces += bm.counts.ambiguous_faces;
    c.degenerate_saddles += bm.counts.degenerate_saddles;
    c.extra_points += bm.counts.extra_points;
    c.centroid_points += bm.counts.centroid_points;
    c.near_sample_points += bm.counts.near_sample_points;
  }
}

}  // namespace

bool merge_bricks(BrickTables& tables, const MergeOrientation& orientation, Mesh& mesh,
                  const Progress& progress) {
  std::vector<BrickMesh>& bricks = tables.bricks;
  const size_t nb = bricks.size();
  const Offsets o = prefix_sums(bricks);
  VertexTable vt = vertex_table(bricks, o);
  const size_t nv = size_t(vt.first.back()), nt = o.triangle.back();
  sum_contour_stats(bricks, mesh.contour);
  tbb::enumerable_thread_specific<Scratch> scratch;
  // Vertices and triangles first; the vertex data is then dropped before
  // the neighbour and part tables are made, which lowers the peak. The
  // mesh's arrays get 2 MB pages where the system allows (fresh_memory.h).
  fresh_resize(mesh.points, 3 * nv, true, true);
  fresh_resize(mesh.normals, 3 * nv, true, true);
  fresh_resize(mesh.triangles, 3 * nt, true, true);
  for_each_brick(nb, [&](size_t b) { place_brick(bricks[b], b, o, vt, orientation, mesh, scratch.local()); });
  for (BrickStores& s : tables.stores) s.vertices.clear();
  fresh_resize(mesh.neighbours, 3 * nt, true, true);
  fresh_resize(mesh.parts, nt, true, true);
  std::vector<int32_t> part_counts(nb, 0);
  // Each brick writes its seam edges at its own offset: in brick order, and
  // in edge order inside a brick.
  const size_t seam_count = o.seam.back();
  ScratchArray<SeamEdge> seams(seam_count);
  for_each_brick(nb, [&](size_t b) {
    brick_topology(bricks[b], b, o, vt, orientation, mesh, part_counts, seams.get(), scratch.local());
  });
  vt.final_index.reset();
  for (BrickStores& s : tables.stores) s.faces.clear();

  progress.stage(ISOFORM_STAGE_TOPOLOGY);
  // Local parts made global: brick b's come after those of bricks before it.
  std::vector<int32_t> part_first(nb + 1, 0);
  for (size_t b = 0; b < nb; ++b) part_first[b + 1] = part_first[b] + part_counts[b];
  // Each brick's local parts are its own, so the bricks count them apart.
  std::vector<int64_t> part_size(size_t(part_first.back()), 0);
  for_each_brick(nb, [&](size_t b) {
    for (size_t t = o.triangle[b]; t < o.triangle[b + 1]; ++t) {
      mesh.parts[t] += part_first[b];
      ++part_size[size_t(mesh.parts[t])];
    }
  });
  TopologyCounts counts;
  bool missing = false;
  for (Scratch& s : scratch) {
    counts.add(s.counts);
    missing |= s.missing_normal;
  }
  std::vector<std::pair<int32_t, int32_t>> links;
  match_seams(seams.get(), seam_count, nv, mesh.neighbours, mesh.parts, counts, links);
  seams.reset();
  mesh.part_count = number_parts(mesh.parts, std::move(part_size), links);
  mesh.stats = MeshStats();
  mesh.stats.boundary_edges = counts.boundary;
  mesh.stats.nonmanifold_edges = counts.nonmanifold;
  mesh.stats.inconsistent_edges = counts.inconsistent;
  mesh.stats.degenerate_triangles = counts.degenerate;
  mesh.stats.euler_characteristic = (long long)nv - counts.edges + (long long)nt;
  return missing;
}

}  // namespace isoform
