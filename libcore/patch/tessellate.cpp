// Tessellation of the side-vertex surface on a barycentric grid, welded by
// construction: vertices first, then every mesh edge's interior samples, then
// every triangle's interior samples, each at an index known in advance.
#include "tessellate.h"

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../errors.h"
#include "../topology.h"
#include "batch_eval.h"

namespace isoform::patch {
namespace {

// Where each sample of the grid lives in the output arrays.
struct Layout {
  int n = 1;                  // steps per edge
  size_t vertices = 0;        // base vertices come first
  size_t edge_base = 0;       // then n - 1 per edge
  size_t interior_base = 0;   // then (n-1)(n-2)/2 per triangle
  size_t interior_per_triangle = 0;
  size_t total = 0;
};

// Index of the interior sample (i, j), i, j >= 1, i + j <= n - 1.
size_t interior_index(int n, int i, int j) {
  // Rows j = 1.. hold n - 1 - j samples each.
  const size_t before = size_t(j - 1) * size_t(n - 1) - size_t(j - 1) * size_t(j) / 2;
  return before + size_t(i - 1);
}

class Grid {
 public:
  Grid(const SideVertexSurface& s, const Layout& l) : s_(s), l_(l) {}

  // Output index of grid sample (i, j) of triangle t (weight i/n on vertex
  // 1, j/n on vertex 2).
  size_t index(size_t t, int i, int j) const {
    const int n = l_.n;
    if (i == 0 && j == 0) return size_t(s_.triangle_vertex(t, 0));
    if (i == n) return size_t(s_.triangle_vertex(t, 1));
    if (j == n) return size_t(s_.triangle_vertex(t, 2));
    if (j == 0) return on_edge(t, 2, i);          // vertex 0 to 1, weight i/n on 1
    if (i == 0) return on_edge(t, 1, j);          // vertex 0 to 2, weight j/n on 2
    if (i + j == n) return on_edge(t, 0, j);      // vertex 1 to 2, weight j/n on 2
    return l_.interior_base + t * l_.interior_per_triangle + interior_index(n, i, j);
  }

 private:
  // Slot `slot`'s edge at weight m/n on the slot's higher-numbered local end
  // (vertex 1 for slot 2, vertex 2 for slots 0 and 1).
  size_t on_edge(size_t t, int slot, int m) const {
    const TriangleEdge te = s_.triangle_edge(t, slot);
    const int32_t far = s_.triangle_vertex(t, slot == 2 ? 1 : 2);
    const int32_t near = s_.triangle_vertex(t, slot == 0 ? 1 : 0);
    const int along = far > near ? m : l_.n - m;  // the curve runs lower to higher
    return l_.edge_base + size_t(te.edge) * size_t(l_.n - 1) + size_t(along - 1);
  }

  const SideVertexSurface& s_;
  const Layout& l_;
};

Layout make_layout(const SideVertexSurface& s, int level) {
  if (level < 0 || level > kMaxTessellationLevel)
    throw InvalidArgument("tessellation: level " + std::to_string(level) + " is outside 0.." +
                          std::to_string(kMaxTessellationLevel));
  Layout l;
  l.n = 1 << level;
  const size_t n = size_t(l.n);
  l.vertices = s.vertex_count();
  l.edge_base = l.vertices;
  l.interior_base = l.edge_base + s.edge_count() * (n - 1);
  l.interior_per_triangle = n >= 2 ? (n - 1) * (n - 2) / 2 : 0;
  l.total = l.interior_base + s.triangle_count() * l.interior_per_triangle;
  const double triangles = double(s.triangle_count()) * double(n) * double(n);
  if (double(l.total) > double(std::numeric_limits<int32_t>::max()) || 3 * triangles > 4e9)
    throw InvalidArgument("tessellation: level " + std::to_string(level) + " would make " +
                          std::to_string((long long)triangles) + " triangles, too many for 32-bit indices");
  return l;
}

void put(Mesh& m, size_t i, const V3d& p, const V3d& n) {
  const double q[3] = {p.x, p.y, p.z}, r[3] = {n.x, n.y, n.z};
  for (int a = 0; a < 3; ++a) {
    m.precise_points[3 * i + a] = q[a];
    m.points[3 * i + a] = float(q[a]);
    m.normals[3 * i + a] = float(r[a]);
  }
}

// +1 when the triangle's winding agrees with its data normals, else -1.
double data_side(const SideVertexSurface& s, size_t t) {
  const V3d& a = s.vertex(size_t(s.triangle_vertex(t, 0)));
  const V3d face = cross(s.vertex(size_t(s.triangle_vertex(t, 1))) - a, s.vertex(size_t(s.triangle_vertex(t, 2))) - a);
  V3d sum(0, 0, 0);
  for (int i = 0; i < 3; ++i) sum = sum + s.vertex_normal(size_t(s.triangle_vertex(t, i)));
  return dot(face, sum) < 0.0 ? -1.0 : 1.0;
}

void check_cancel(const Progress& progress, std::atomic<size_t>& done, size_t add, size_t total) {
  if (progress.cancelled()) throw Cancelled("tessellation cancelled");
  const size_t now = done.fetch_add(add) + add;
  progress.fraction(float(double(now) / double(total ? total : 1)));
}

}  // namespace

Mesh tessellate(const SideVertexSurface& s, int level, const Progress& progress, TessellationStats* stats) {
  const Layout l = make_layout(s, level);
  const int n = l.n;
  Mesh m;
  m.precise_points.assign(3 * l.total, 0.0);
  m.points.assign(3 * l.total, 0.0f);
  m.normals.assign(3 * l.total, 0.0f);
  // Phase 1: the base vertices with their normals.
  for (size_t v = 0; v < l.vertices; ++v) put(m, v, s.vertex(v), s.vertex_normal(v));
  // Phase 2: each edge's interior samples, from its curve.
  const size_t work = s.edge_count() + s.triangle_count();
  std::atomic<size_t> done{0};
  std::atomic<bool> cancelled{false};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, s.edge_count(), 256), [&](const tbb::blocked_range<size_t>& r) {
    if (progress.cancelled()) { cancelled = true; return; }
    for (size_t e = r.begin(); e < r.end(); ++e)
      for (int k = 1; k < n; ++k) {
        const EdgeValue<double> ev = edge_eval(s.edge_curve(e), double(k) / n);
        put(m, l.edge_base + e * size_t(n - 1) + size_t(k - 1), ev.point, ev.normal);
      }
    const size_t now = done.fetch_add(r.size()) + r.size();
    progress.fraction(float(double(now) / double(work ? work : 1)));
  });
  if (cancelled || progress.cancelled()) throw Cancelled("tessellation cancelled");
  // Phase 3: interior samples and the triangles of each base triangle.
  const Grid grid(s, l);
  const size_t per = size_t(n) * size_t(n);
  m.triangles.assign(3 * s.triangle_count() * per, 0);
  std::atomic<long long> flat{0}, reversed{0};
  // The interior lattice (i, j), evaluated per triangle in one batch.
  std::vector<int> li, lj;
  std::vector<double> lu, lv;
  for (int j = 1; j < n; ++j)
    for (int i = 1; i + j < n; ++i) {
      li.push_back(i);
      lj.push_back(j);
      lu.push_back(double(i) / n);
      lv.push_back(double(j) / n);
    }
  const BatchPlan plan(s.options(), lu.data(), lv.data(), lu.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, s.triangle_count(), 64), [&](const tbb::blocked_range<size_t>& r) {
    if (cancelled) return;
    std::vector<SurfaceSample> xs(lu.size());
    std::unique_ptr<bool[]> ok(new bool[lu.size() + 1]);
    for (size_t t = r.begin(); t < r.end(); ++t) {
      const double side = data_side(s, t);
      evaluate_batch(s, t, plan, xs.data(), ok.get(), false);
      for (size_t k = 0; k < lu.size(); ++k) {
        const int i = li[k], j = lj[k];
        const double u = lu[k], v = lv[k];
        const SurfaceSample& x = xs[k];
        const size_t at = grid.index(t, i, j);
        V3d data = (1 - u - v) * s.vertex_normal(size_t(s.triangle_vertex(t, 0))) +
                   u * s.vertex_normal(size_t(s.triangle_vertex(t, 1))) +
                   v * s.vertex_normal(size_t(s.triangle_vertex(t, 2)));
        if (ok[k]) {
          const V3d normal = side * V3d::from(x.normal);
          if (dot(normal, data) < 0.0) reversed.fetch_add(1);
          put(m, at, V3d::from(x.point), normal);
        } else {
          // NOTE: undefined data (never NaN in the output): the flat point.
          flat.fetch_add(1);
          const V3d p = (1 - u - v) * s.vertex(size_t(s.triangle_vertex(t, 0))) +
                        u * s.vertex(size_t(s.triangle_vertex(t, 1))) + v * s.vertex(size_t(s.triangle_vertex(t, 2)));
          const double len = norm(data);
          put(m, at, p, len > 0 ? (1 / len) * data : V3d(0, 0, 1));
        }
      }
      int32_t* out = &m.triangles[3 * t * per];
      for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
          const int32_t a = int32_t(grid.index(t, i, j)), b = int32_t(grid.index(t, i + 1, j)),
                        c = int32_t(grid.index(t, i, j + 1));
          *out++ = a, *out++ = b, *out++ = c;
          if (i + j + 1 < n) {
            const int32_t d = int32_t(grid.index(t, i + 1, j + 1));
            *out++ = b, *out++ = d, *out++ = c;
          }
        }
    }
    try {
      check_cancel(progress, done, r.size(), work);
    } catch (const Cancelled&) {
      cancelled = true;
    }
  });
  if (cancelled) throw Cancelled("tessellation cancelled");
  if (stats) {
    stats->flat_samples = flat;
    stats->reversed_samples = reversed;
  }
  compute_topology(m);
  return m;
}

}  // namespace isoform::patch
