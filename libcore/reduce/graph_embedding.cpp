// Graph-mode inputs (see graph_embedding.h): the triangles' turning, the
// boundary loop, and the loop's simplicity through a hashed grid of its
// edges.
#include "graph_embedding.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "../errors.h"

namespace isoform::reduce {
namespace {

struct XY {
  double x, y;
};

// The projected points, in double (precise when the mesh has them).
struct Projection {
  const Mesh& mesh;
  bool precise;
  explicit Projection(const Mesh& m) : mesh(m), precise(m.precise_points.size() == m.points.size()) {}
  XY operator()(int32_t v) const {
    const size_t i = 3 * size_t(v);
    if (precise) return {mesh.precise_points[i], mesh.precise_points[i + 1]};
    return {double(mesh.points[i]), double(mesh.points[i + 1])};
  }
};

// The sign of the turn a -> b -> c: +1 counterclockwise, -1 clockwise, 0
// when the floating-point determinant is within its error bound (Shewchuk's
// first orientation bound), or NaN, or its products are too small (below
// 1e-300, where the bound no longer holds) or overflow: coordinate
// differences between about 1e-150 and 1e150 are decided.
int turn(const XY& a, const XY& b, const XY& c) {
  const double left = (a.x - c.x) * (b.y - c.y);
  const double right = (a.y - c.y) * (b.x - c.x);
  const double det = left - right;
  const double sum = std::fabs(left) + std::fabs(right);
  if (!(sum > 1e-300)) return 0;
  const double bound = 3.3306690738754716e-16 * sum;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return 0;
}

// The first triangle whose projection is not certainly counterclockwise, or
// -1.
int64_t first_not_counterclockwise(const Mesh& mesh, const Projection& xy) {
  const int64_t nt = int64_t(mesh.triangle_count());
  return tbb::parallel_reduce(
      tbb::blocked_range<int64_t>(0, nt), int64_t(-1),
      [&](const tbb::blocked_range<int64_t>& r, int64_t first) {
        if (first >= 0 && first < r.begin()) return first;
        for (int64_t t = r.begin(); t != r.end(); ++t) {
          const int32_t* v = &mesh.triangles[3 * size_t(t)];
          if (turn(xy(v[0]), xy(v[1]), xy(v[2])) <= 0) return first >= 0 ? std::min(first, t) : t;
        }
        return first;
      },
      [](int64_t a, int64_t b) { return a < 0 ? b : b < 0 ? a : std::min(a, b); });
}

// The corner of triangle t after (step 1) or before (step 2) vertex a.
int32_t corner_beside(const Mesh& mesh, int32_t t, int32_t a, int step) {
  const int32_t* v = &mesh.triangles[3 * size_t(t)];
  const int k = v[0] == a ? 0 : v[1] == a ? 1 : 2;
  return v[(k + step) % 3];
}

// The boundary as one loop of vertices, each followed by the next along its
// boundary edge; empty when there is no boundary or more than one loop.
std::vector<int32_t> boundary_loop(const Mesh& mesh, const VertexStars& stars) {
  const size_t nv = stars.vertex_count();
  std::vector<int32_t> next(nv, -1);
  std::atomic<bool> odd{false};
  // Edge a -> b of a triangle is on the boundary when no triangle of a's
  // star has b just before a (the edge's other side, b -> a).
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t a = r.begin(); a != r.end(); ++a) {
      for (const int32_t* t = stars.begin(a); t != stars.end(a); ++t) {
        const int32_t b = corner_beside(mesh, *t, int32_t(a), 1);
        bool inner = false;
        for (const int32_t* u = stars.begin(a); u != stars.end(a) && !inner; ++u)
          inner = corner_beside(mesh, *u, int32_t(a), 2) == b;
        if (inner) continue;
        if (next[a] >= 0) odd.store(true, std::memory_order_relaxed);
        next[a] = b;
      }
    }
  });
  if (odd.load()) return {};
  size_t count = 0;
  int32_t first = -1;
  for (size_t v = 0; v < nv; ++v)
    if (next[v] >= 0) {
      if (first < 0) first = int32_t(v);
      ++count;
    }
  std::vector<int32_t> loop;
  if (first < 0) return loop;
  loop.reserve(count);
  int32_t v = first;
  do {
    loop.push_back(v);
    v = next[size_t(v)];
  } while (v >= 0 && v != first && loop.size() <= count);
  if (v != first || loop.size() != count) loop.clear();
  return loop;
}

// a < b < c or a > b > c.
bool strictly_between(double a, double b, double c) { return (a < b && b < c) || (a > b && b > c); }

// Edges (a, b) and (b, c) meet only at b.
bool meet_only_at_shared(const XY& a, const XY& b, const XY& c) {
  return strictly_between(a.x, b.x, c.x) || strictly_between(a.y, b.y, c.y) || turn(a, b, c) != 0;
}

// Edges (a, b) and (c, d) do not meet.
bool apart(const XY& a, const XY& b, const XY& c, const XY& d) {
  if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x)) return true;
  if (std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y)) return true;
  const int sc = turn(a, b, c), sd = turn(a, b, d);
  if (sc != 0 && sc == sd) return true;
  const int sa = turn(c, d, a), sb = turn(c, d, b);
  return sa != 0 && sa == sb;
}

// The loop's projection is a simple polygon: edges i and i + 1 meet only at
// their shared vertex, other edges not at all. Edges are entered in the
// cells of a hashed grid (about the mean edge's size) that their boxes meet,
// and the edges of a cell are tested in pairs. Gives up (false) when the
// cells or the pairs grow beyond a few dozen per edge.
bool loop_is_simple(const std::vector<XY>& p) {
  const size_t m = p.size();
  if (m < 3) return false;
  double lo_x = p[0].x, lo_y = p[0].y, size = 0;
  for (size_t i = 0; i < m; ++i) {
    const XY& a = p[i];
    const XY& b = p[(i + 1) % m];
    lo_x = std::min(lo_x, a.x);
    lo_y = std::min(lo_y, a.y);
    size += std::max(std::fabs(b.x - a.x), std::fabs(b.y - a.y));
  }
  const double cell = size / double(m);
  if (!(cell > 0) || !std::isfinite(cell)) return false;
  const size_t budget = 32 * m + 4096;
  std::vector<std::pair<uint64_t, uint32_t>> entries;  // (cell, edge)
  entries.reserve(2 * m);
  for (size_t i = 0; i < m; ++i) {
    const XY& a = p[i];
    const XY& b = p[(i + 1) % m];
    const auto index = [&](double v, double lo) { return int64_t(std::floor((v - lo) / cell)); };
    const int64_t x0 = index(std::min(a.x, b.x), lo_x), x1 = index(std::max(a.x, b.x), lo_x);
    const int64_t y0 = index(std::min(a.y, b.y), lo_y), y1 = index(std::max(a.y, b.y), lo_y);
    if (x0 < 0 || y0 < 0 || x1 >= (int64_t(1) << 31) || y1 >= (int64_t(1) << 31)) return false;
    if (size_t((x1 - x0 + 1) * (y1 - y0 + 1)) > budget - entries.size()) return false;
    for (int64_t x = x0; x <= x1; ++x)
      for (int64_t y = y0; y <= y1; ++y) entries.emplace_back((uint64_t(x) << 32) | uint64_t(y), uint32_t(i));
  }
  std::sort(entries.begin(), entries.end());
  size_t pairs = 0;
  for (size_t s = 0; s < entries.size();) {
    size_t e = s;
    while (e < entries.size() && entries[e].first == entries[s].first) ++e;
    for (size_t u = s; u < e; ++u)
      for (size_t w = u + 1; w < e; ++w) {
        if (++pairs > budget) return false;
        const size_t i = entries[u].second, j = entries[w].second;  // i < j
        const XY &a = p[i], &b = p[(i + 1) % m], &c = p[j], &d = p[(j + 1) % m];
        if (j == i + 1) {
          if (!meet_only_at_shared(a, b, d)) return false;
        } else if (i == 0 && j == m - 1) {
          if (!meet_only_at_shared(c, a, b)) return false;
        } else if (!apart(a, b, c, d)) {
          return false;
        }
      }
    s = e;
  }
  return true;
}

}  // namespace

void validate_graph(const Mesh& mesh, const std::string& what) {
  const Projection xy(mesh);
  const int64_t t = first_not_counterclockwise(mesh, xy);
  if (t < 0) return;
  const int32_t* v = &mesh.triangles[3 * size_t(t)];
  throw InvalidArgument(what + ": not a graph z = f(x, y): triangle " + std::to_string(t) + " (vertices " +
                        std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) +
                        ") does not turn counterclockwise seen from +z (graph mode needs every triangle "
                        "so, the normals up)");
}

bool projects_one_to_one(const Mesh& mesh, const VertexStars& stars) {
  const Projection xy(mesh);
  const std::vector<int32_t> loop = boundary_loop(mesh, stars);
  if (loop.empty()) return false;
  std::vector<XY> polygon(loop.size());
  for (size_t i = 0; i < loop.size(); ++i) polygon[i] = xy(loop[i]);
  return loop_is_simple(polygon);
}

}  // namespace isoform::reduce
