// The broad phase of the self-overlap check (see mesh_overlap.h). Cells are
// grouped into buckets of 4 x 4 x 4 (a counting sort), each bucket ordered
// by cell and tested in parallel.
#include "mesh_overlap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "../stretch_sort.h"
#include "big_vector.h"

namespace isoform::reduce {
namespace {

constexpr int kCellBits = 21;  // per axis: cell keys pack three into 63 bits
constexpr int64_t kCellMax = (int64_t(1) << kCellBits) - 1;

struct Box {
  float lo[3], hi[3];
  bool valid;
  bool oversized;  // left out of the grid (take_oversized)
};

struct Entry {
  uint64_t key;
  int32_t triangle;
  // Bit k: this cell is the first of the triangle's box along axis k. A
  // pair's common box starts in the cell where, on every axis, one of the two
  // starts, so (a.first | b.first) == 7 tests the pair in that cell only.
  // The higher bits are free (find_overlaps keeps a slot there).
  uint32_t first;
  bool operator<(const Entry& o) const { return key != o.key ? key < o.key : triangle < o.triangle; }
};

// The corners of triangle t, in double.
struct Corners {
  const Mesh& mesh;
  bool precise;
  explicit Corners(const Mesh& m) : mesh(m), precise(m.precise_points.size() == m.points.size()) {}
  Point3 point(int32_t v) const {
    const size_t i = 3 * size_t(v);
    if (precise) return {mesh.precise_points[i], mesh.precise_points[i + 1], mesh.precise_points[i + 2]};
    return {double(mesh.points[i]), double(mesh.points[i + 1]), double(mesh.points[i + 2])};
  }
  void of(size_t t, Point3 out[3]) const {
    for (int k = 0; k < 3; ++k) out[k] = point(mesh.triangles[3 * t + size_t(k)]);
  }
};

// Float boxes rounded outward, so that they hold the double triangles.
BigVector<Box> triangle_boxes(const Corners& corners, size_t nt) {
  BigVector<Box> boxes(nt);
  tbb::parallel_for(size_t(0), nt, [&](size_t t) {
    Point3 p[3];
    corners.of(t, p);
    Box& b = boxes[t];
    b.valid = true;
    b.oversized = false;
    for (int k = 0; k < 3; ++k) {
      const double lo = std::min({p[0][k], p[1][k], p[2][k]}), hi = std::max({p[0][k], p[1][k], p[2][k]});
      b.valid &= std::isfinite(lo) && std::isfinite(hi);
      b.lo[k] = float(lo);
      b.hi[k] = float(hi);
      if (double(b.lo[k]) > lo) b.lo[k] = std::nextafter(b.lo[k], -INFINITY);
      if (double(b.hi[k]) < hi) b.hi[k] = std::nextafter(b.hi[k], INFINITY);
    }
  });
  return boxes;
}

struct Grid {
  double origin[3] = {0, 0, 0};
  double inverse_size = 1.0;

  // (Clamped first, then truncated: the same as the floor of the clamped
  // value, without the call std::floor is on this target.)
  int64_t cell(float x, int k) const {
    const double c = (double(x) - origin[k]) * inverse_size;
    return int64_t(std::clamp(c, 0.0, double(kCellMax)));
  }
  static uint64_t key(int64_t x, int64_t y, int64_t z) {
    return uint64_t(x) | uint64_t(y) << kCellBits | uint64_t(z) << (2 * kCellBits);
  }
};

// Cells about the mean box size, at most 2^21 along the largest extent.
Grid make_grid(const BigVector<Box>& boxes) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, sum = 0;
  size_t n = 0;
  for (const Box& b : boxes) {
    if (!b.valid) continue;
    double extent = 0;
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], double(b.lo[k]));
      hi[k] = std::max(hi[k], double(b.hi[k]));
      extent = std::max(extent, double(b.hi[k]) - double(b.lo[k]));
    }
    sum += extent;
    ++n;
  }
  Grid g;
  if (n == 0) return g;
  const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  double size = std::max(sum / double(n), span / double(kCellMax - 1));
  if (!(size > 0)) size = 1.0;
  for (int k = 0; k < 3; ++k) g.origin[k] = lo[k];
  g.inverse_size = 1.0 / size;
  return g;
}

// The cells a box covers, per axis (none when the box is not valid).
struct CellRange {
  int32_t lo[3] = {0, 0, 0}, hi[3] = {-1, -1, -1};
  size_t count() const { return size_t(hi[0] - lo[0] + 1) * size_t(hi[1] - lo[1] + 1) * size_t(hi[2] - lo[2] + 1); }
};

// NOTE: computed again wherever it is needed rather than kept per triangle:
// six roundings are cheaper than 24 MB of fresh memory (a first write of a
// page costs more than the arithmetic, and most of the check's time was
// the kernel clearing pages).
inline CellRange cell_range(const Box& b, const Grid& g) {
  CellRange r;
  if (!b.valid || b.oversized) return r;
  for (int k = 0; k < 3; ++k) {
    r.lo[k] = int32_t(g.cell(b.lo[k], k));
    r.hi[k] = int32_t(g.cell(b.hi[k], k));
  }
  return r;
}

// NOTE: buckets hold whole blocks of 4 x 4 x 4 cells, not single cells: a
// bucket's triangles are neighbours, gathered once for all the block's
// cells, and consecutive triangles of the input mostly fill the same
// bucket. The grid is cut into slabs one block thick across its longest
// axis, each tested on its own (side by side): only the entries of the
// slabs under test exist (a megabyte or two each, in cache, instead of
// 86 MB written once and read once for a 1M-triangle contour: the first
// write of fresh memory, a page fault and a zeroing per page, costs more
// than the check's own work on those bytes). Within a slab the blocks are
// numbered along the other two axes when they are few enough, else by a
// hash of the block.
constexpr int kBlockBits = 2;

// The slab axis and the two others, and the grid's extent in blocks.
struct SlabAxes {
  int axis = 2, u = 0, v = 1;
  int32_t blocks[3] = {1, 1, 1};
  int32_t block(int32_t cell) const { return cell >> kBlockBits; }
};

// The cells of range r within slab `slab`, with their Entry::first bits.
template <class Visit>
void for_cells(const CellRange& r, const SlabAxes& s, int32_t slab, Visit visit) {
  int32_t lo[3] = {r.lo[0], r.lo[1], r.lo[2]}, hi[3] = {r.hi[0], r.hi[1], r.hi[2]};
  lo[s.axis] = std::max(lo[s.axis], slab << kBlockBits);
  hi[s.axis] = std::min(hi[s.axis], ((slab + 1) << kBlockBits) - 1);
  for (int32_t z = lo[2]; z <= hi[2]; ++z)
    for (int32_t y = lo[1]; y <= hi[1]; ++y)
      for (int32_t x = lo[0]; x <= hi[0]; ++x)
        visit(Grid::key(x, y, z), uint32_t(x == r.lo[0]) | uint32_t(y == r.lo[1]) << 1 | uint32_t(z == r.lo[2]) << 2);
}

struct BucketMap {
  SlabAxes axes;
  bool dense = false;
  int bits = 1;
  size_t count = 2;
  size_t operator()(uint64_t key) const {
    const int32_t c[3] = {int32_t(key & uint64_t(kCellMax)), int32_t((key >> kCellBits) & uint64_t(kCellMax)),
                          int32_t(key >> (2 * kCellBits))};
    const uint64_t u = uint64_t(axes.block(c[axes.u])), v = uint64_t(axes.block(c[axes.v]));
    if (dense) return size_t(u + uint64_t(axes.blocks[axes.u]) * v);
    return size_t((Grid::key(int64_t(u), int64_t(v), 0) * 0x9E3779B97F4A7C15ull) >> (64 - bits));
  }
};

// The buckets of a slab of `entries` entries.
BucketMap bucket_map(const SlabAxes& axes, size_t entries) {
  BucketMap m;
  m.axes = axes;
  const double count = double(axes.blocks[axes.u]) * double(axes.blocks[axes.v]);
  if (count <= 4.0 * double(entries) + 64.0) {
    m.dense = true;
    m.count = size_t(count);
    return m;
  }
  while (m.bits < 40 && (size_t(1) << m.bits) < entries / 64) ++m.bits;  // about 64 entries a bucket
  m.count = size_t(1) << m.bits;
  return m;
}

// The cell of key within its block, 0 to 63, in the order of the keys.
uint32_t cell_in_block(uint64_t key) {
  constexpr uint64_t mask = (uint64_t(1) << kBlockBits) - 1;
  return uint32_t((key & mask) | ((key >> kCellBits) & mask) << kBlockBits |
                  ((key >> (2 * kCellBits)) & mask) << (2 * kBlockBits));
}

// Orders the entries of one block by cell, stably (a counting sort).
void group_by_cell(Entry* first, Entry* last, std::vector<Entry>& scratch) {
  constexpr int kCells = 1 << (3 * kBlockBits);
  uint32_t start[kCells + 1] = {};
  for (const Entry* i = first; i != last; ++i) ++start[cell_in_block(i->key) + 1];
  for (int c = 0; c < kCells; ++c) start[c + 1] += start[c];
  scratch.resize(size_t(last - first));
  for (const Entry* i = first; i != last; ++i) scratch[start[cell_in_block(i->key)]++] = *i;
  std::copy(scratch.begin(), scratch.end(), first);
}

// Every slab's triangles, ascending (a counting sort: a triangle is listed
// in each slab its range reaches, most in one or two).
struct Slabs {
  SlabAxes axes;
  std::vector<int32_t> triangles;
  std::vector<size_t> start;  // per slab, into triangles
};

// NOTE: the grid's extent and the slabs' lists in a few stretches of
// triangles side by side (stretch_sort.h; a serial walk over every
// triangle's range would leave the other threads idle through a sizeable
// part of the check), each slab's triangles ascending.
Slabs slabs_of(const BigVector<Box>& boxes, const Grid& g) {
  Slabs s;
  SlabAxes& a = s.axes;
  const size_t n = boxes.size();
  const size_t stretches = n < 65536 ? 1 : size_t(std::clamp(tbb::this_task_arena::max_concurrency(), 1, 4));
  const size_t per = (n + stretches - 1) / stretches;
  std::vector<std::array<int32_t, 3>> top(stretches, std::array<int32_t, 3>{1, 1, 1});
  tbb::parallel_for(size_t(0), stretches, [&](size_t k) {
    for (size_t t = k * per; t < std::min(n, (k + 1) * per); ++t) {
      const CellRange r = cell_range(boxes[t], g);
      for (int c = 0; c < 3; ++c) top[k][size_t(c)] = std::max(top[k][size_t(c)], a.block(r.hi[c]) + 1);
    }
  });
  for (const auto& t : top)
    for (int c = 0; c < 3; ++c) a.blocks[c] = std::max(a.blocks[c], t[size_t(c)]);
  a.axis = int(std::max_element(a.blocks, a.blocks + 3) - a.blocks);
  a.u = (a.axis + 1) % 3;
  a.v = (a.axis + 2) % 3;
  sort_by_keys_in_stretches(
      n, size_t(a.blocks[a.axis]),
      [&](size_t t, auto visit) {
        const CellRange r = cell_range(boxes[t], g);
        if (r.lo[0] > r.hi[0]) return;
        for (int32_t slab = a.block(r.lo[a.axis]); slab <= a.block(r.hi[a.axis]); ++slab) visit(size_t(slab));
      },
      s.start, s.triangles);
  return s;
}

// One slab's (cell, triangle) entries grouped by bucket (a counting sort),
// each bucket in triangle order, each triangle's entries together.
struct Buckets {
  std::vector<size_t> start;  // per bucket, into entries
  std::vector<Entry> entries;
  bool dense = false;  // each bucket one block (BucketMap::dense)
};

void fill_slab(const BigVector<Box>& boxes, const Grid& g, const Slabs& slabs, int32_t slab, Buckets& out) {
  const int32_t* first = slabs.triangles.data() + slabs.start[size_t(slab)];
  const int32_t* last = slabs.triangles.data() + slabs.start[size_t(slab) + 1];
  const SlabAxes& a = slabs.axes;
  size_t n = 0;
  for (const int32_t* t = first; t != last; ++t) {
    const CellRange r = cell_range(boxes[size_t(*t)], g);
    const int32_t across = std::min(((slab + 1) << kBlockBits) - 1, r.hi[a.axis]) -
                           std::max(slab << kBlockBits, r.lo[a.axis]) + 1;
    n += size_t(across) * size_t(r.hi[a.u] - r.lo[a.u] + 1) * size_t(r.hi[a.v] - r.lo[a.v] + 1);
  }
  const BucketMap bucket = bucket_map(a, n);
  out.dense = bucket.dense;
  out.start.assign(bucket.count + 1, 0);
  out.entries.resize(n);
  for (const int32_t* t = first; t != last; ++t)
    for_cells(cell_range(boxes[size_t(*t)], g), a, slab, [&](uint64_t key, uint32_t) { ++out.start[bucket(key) + 1]; });
  for (size_t b = 0; b < bucket.count; ++b) out.start[b + 1] += out.start[b];
  std::vector<size_t>& next = out.start;  // (moved back below)
  for (const int32_t* t = first; t != last; ++t)
    for_cells(cell_range(boxes[size_t(*t)], g), a, slab,
              [&](uint64_t key, uint32_t bits) { out.entries[next[bucket(key)]++] = {key, *t, bits}; });
  // Each bucket's start was moved to its end, the next one's start.
  for (size_t b = bucket.count; b > 0; --b) out.start[b] = out.start[b - 1];
  out.start[0] = 0;
}

bool boxes_meet(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

// The largest side of a box.
double extent(const Box& b) {
  return std::max({double(b.hi[0]) - double(b.lo[0]), double(b.hi[1]) - double(b.lo[1]),
                   double(b.hi[2]) - double(b.lo[2])});
}

// A bucket's triangles with what every pair test reads: corners, normal,
// box and vertex indices, gathered once per bucket instead of once per pair.
struct LocalTriangle {
  Point3 p[3];
  Point3 n;
  Box box;
  double extent;  // of box
  int32_t v[3];
};

struct BucketScratch {
  Buckets buckets;              // of the slab under test
  std::vector<int32_t> ids;     // the bucket's triangles, ascending
  std::vector<LocalTriangle> local;
  std::vector<Entry> sorted;    // group_by_cell's
  std::vector<OverlapPair> found;
};

LocalTriangle local_triangle(const Mesh& mesh, const Corners& corners, const BigVector<Box>& boxes, size_t id) {
  LocalTriangle t;
  corners.of(id, t.p);
  t.n = triangle_normal(t.p);
  t.box = boxes[id];
  t.extent = extent(t.box);
  for (int c = 0; c < 3; ++c) t.v[c] = mesh.triangles[3 * id + size_t(c)];
  return t;
}

// The full test of a pair whose boxes meet.
PairOverlap test_pair(const LocalTriangle& ta, const LocalTriangle& tb) {
  // Boxes that meet lie in a box whose sides are at most the sums of
  // theirs (the float boxes hold the triangles).
  if (certainly_apart(ta.p, ta.n, ta.v, tb.p, tb.n, tb.v, ta.extent + tb.extent)) return {};
  return triangles_overlap(ta.p, ta.n, ta.v, tb.p, tb.n, tb.v);
}

// NOTE: a triangle much larger than the cells (a ground quad under a
// detailed model) would fill millions of cells: a tilted 60 x 60 quad beside
// a 20,000-triangle sphere of radius 1 covers so many cells of the sphere's
// size that their entries alone run to gigabytes. A triangle whose
// box covers more cells than the triangles number over 32 (and over 512) is
// left out of the grid and tested against every triangle's box instead: n
// box tests rather than more than n / 32 entries, each written, sorted and
// compared.
std::vector<int32_t> take_oversized(BigVector<Box>& boxes, const Grid& g) {
  const size_t limit = std::max<size_t>(512, boxes.size() / 32);
  tbb::parallel_for(size_t(0), boxes.size(), [&](size_t t) {
    boxes[t].oversized = boxes[t].valid && cell_range(boxes[t], g).count() > limit;
  });
  std::vector<int32_t> oversized;
  for (size_t t = 0; t < boxes.size(); ++t)
    if (boxes[t].oversized) oversized.push_back(int32_t(t));
  return oversized;
}

// The pairs with an oversized triangle, each once, a < b.
std::vector<OverlapPair> oversized_pairs(const Mesh& mesh, const Corners& corners, const BigVector<Box>& boxes,
                                         const std::vector<int32_t>& oversized) {
  std::vector<LocalTriangle> big;
  for (int32_t b : oversized) big.push_back(local_triangle(mesh, corners, boxes, size_t(b)));
  tbb::enumerable_thread_specific<std::vector<OverlapPair>> found;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, boxes.size()), [&](const tbb::blocked_range<size_t>& r) {
    std::vector<OverlapPair>& out = found.local();
    for (size_t t = r.begin(); t != r.end(); ++t) {
      if (!boxes[t].valid) continue;
      // An oversized t meets the oversized ones after it only (each pair once).
      const auto self = std::lower_bound(oversized.begin(), oversized.end(), int32_t(t));
      const bool is_big = self != oversized.end() && *self == int32_t(t);
      const size_t from = is_big ? size_t(self - oversized.begin()) + 1 : 0;
      for (size_t k = from; k < big.size(); ++k) {
        if (!big[k].box.valid || !boxes_meet(boxes[t], big[k].box)) continue;
        const LocalTriangle mine = local_triangle(mesh, corners, boxes, t);
        const PairOverlap o = test_pair(mine, big[k]);
        const int32_t a = int32_t(t), b = oversized[k];
        if (o.overlap) out.push_back({std::min(a, b), std::max(a, b), o.near});
      }
    }
  });
  std::vector<OverlapPair> all;
  for (auto& part : found) all.insert(all.end(), part.begin(), part.end());
  return all;
}

}  // namespace

std::vector<OverlapPair> find_overlaps(const Mesh& mesh) {
  const Corners corners(mesh);
  BigVector<Box> boxes = triangle_boxes(corners, mesh.triangle_count());
  const Grid grid = make_grid(boxes);
  const std::vector<int32_t> oversized = take_oversized(boxes, grid);
  const Slabs slabs = slabs_of(boxes, grid);
  tbb::enumerable_thread_specific<BucketScratch> scratch;
  // The pairs of one cell [e, e + count): each pair whose common box starts
  // in this cell.
  auto test_cell = [&](const Entry* e, size_t count, BucketScratch& b) {
    for (size_t p = 0; p < count; ++p)
      for (size_t q = p + 1; q < count; ++q) {
        if (((e[p].first | e[q].first) & 7) != 7) continue;
        const LocalTriangle& ta = b.local[size_t(e[p].first >> 3)];
        const LocalTriangle& tb = b.local[size_t(e[q].first >> 3)];
        if (!boxes_meet(ta.box, tb.box)) continue;
        const PairOverlap o = test_pair(ta, tb);
        if (o.overlap) b.found.push_back({e[p].triangle, e[q].triangle, o.near});  // a < b: sorted
      }
  };
  // The slabs side by side, each bucket of a slab in turn.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, slabs.start.size() - 1, 1), [&](const tbb::blocked_range<size_t>& r) {
    BucketScratch& b = scratch.local();
    for (size_t slab = r.begin(); slab != r.end(); ++slab) {
      if (slabs.start[slab + 1] - slabs.start[slab] < 2) continue;
      fill_slab(boxes, grid, slabs, int32_t(slab), b.buckets);
      for (size_t k = 0; k + 1 < b.buckets.start.size(); ++k) {
        Entry* first = b.buckets.entries.data() + b.buckets.start[k];
        Entry* last = b.buckets.entries.data() + b.buckets.start[k + 1];
        if (last - first < 2) continue;
        // The entries were filled in triangle order, each triangle's together:
        // its slot among the bucket's triangles goes into the high bits of
        // Entry::first.
        b.ids.clear();
        for (Entry* i = first; i != last; ++i) {
          if (b.ids.empty() || b.ids.back() != i->triangle) b.ids.push_back(i->triangle);
          i->first |= uint32_t(b.ids.size() - 1) << 3;
        }
        b.local.resize(b.ids.size());
        for (size_t i = 0; i < b.ids.size(); ++i) b.local[i] = local_triangle(mesh, corners, boxes, size_t(b.ids[i]));
        // Equal cells together, each in triangle order: in a dense map a
        // bucket is one block, ordered by the cell within it (a stable
        // counting sort); else sorted by (cell, triangle).
        if (b.buckets.dense)
          group_by_cell(first, last, b.sorted);
        else
          std::sort(first, last);
        for (Entry* i = first; i != last;) {
          Entry* end = i;
          while (end != last && end->key == i->key) ++end;
          if (end - i > 1) test_cell(i, size_t(end - i), b);
          i = end;
        }
      }
    }
  });
  std::vector<OverlapPair> all = oversized_pairs(mesh, corners, boxes, oversized);
  for (auto& part : scratch) all.insert(all.end(), part.found.begin(), part.found.end());
  std::sort(all.begin(), all.end(),
            [](const OverlapPair& x, const OverlapPair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  return all;
}

}  // namespace isoform::reduce
