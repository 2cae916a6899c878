// Hamann (1991), Section 3.3: neighbours (Algorithm 3.1) and parts
// (Algorithm 3.2) of a triangulation, in O(n) via a vertex-to-triangle table
// (vertex_stars.h).
#include "topology.h"

#include <algorithm>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "vertex_stars.h"

namespace isoform {
namespace {

int corner_of(const int32_t* tri, int32_t v) { return tri[0] == v ? 0 : tri[1] == v ? 1 : tri[2] == v ? 2 : -1; }

bool degenerate(const Mesh& mesh, size_t t) {
  const int32_t* tri = &mesh.triangles[3 * t];
  if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) return true;
  const float* p = &mesh.points[3 * size_t(tri[0])];
  const float* q = &mesh.points[3 * size_t(tri[1])];
  const float* r = &mesh.points[3 * size_t(tri[2])];
  const double u[3] = {double(q[0]) - p[0], double(q[1]) - p[1], double(q[2]) - p[2]};
  const double w[3] = {double(r[0]) - p[0], double(r[1]) - p[1], double(r[2]) - p[2]};
  const double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  return c[0] == 0 && c[1] == 0 && c[2] == 0;
}

// What one stretch of triangles finds: the stats' counts and the edges
// whose lowest triangle is in it.
struct EdgeCounts {
  MeshStats stats;
  long long edges = 0;
  void add(const EdgeCounts& o) {
    stats.boundary_edges += o.stats.boundary_edges;
    stats.nonmanifold_edges += o.stats.nonmanifold_edges;
    stats.inconsistent_edges += o.stats.inconsistent_edges;
    stats.degenerate_triangles += o.stats.degenerate_triangles;
    edges += o.edges;
  }
};

// Triangle t's neighbours into mesh.neighbours, its counts into c.
void triangle_neighbours(Mesh& mesh, const VertexStars& stars, size_t t, EdgeCounts& c) {
  const int32_t* tri = &mesh.triangles[3 * t];
  c.stats.degenerate_triangles += degenerate(mesh, t);
  for (int i = 0; i < 3; ++i) {
    const int32_t a = tri[i], b = tri[(i + 1) % 3];
    // Every triangle around a that also holds b shares the edge (a, b).
    int count = 0, other = -1;
    bool same_direction = false, lowest = true;
    for (const int32_t* s = stars.begin(size_t(a)); s != stars.end(size_t(a)); ++s) {
      const int32_t u = *s;
      if (size_t(u) == t) continue;
      const int32_t* ut = &mesh.triangles[3 * size_t(u)];
      const int cb = corner_of(ut, b);
      if (cb < 0) continue;
      ++count;
      other = u;
      if (size_t(u) < t) lowest = false;
      // A consistent neighbour runs the edge from b to a; one that runs it
      // from a to b (a just before b) is inconsistently oriented.
      if (ut[(cb + 2) % 3] == a) same_direction = true;
    }
    if (lowest) ++c.edges;  // each edge counted once, by its lowest triangle
    if (count == 0) {
      ++c.stats.boundary_edges;
    } else if (count == 1) {
      mesh.neighbours[3 * t + size_t(i)] = other;
      if (same_direction && size_t(other) > t) ++c.stats.inconsistent_edges;
    } else if (lowest) {
      ++c.stats.nonmanifold_edges;
    }
  }
}

}  // namespace

// NOTE: each triangle writes its own three neighbours and counts into its
// stretch's sums, so the triangles go side by side; the counts are sums,
// the same for any split.
void compute_neighbours(Mesh& mesh) {
  const size_t m = mesh.triangle_count();
  mesh.neighbours.assign(3 * m, -1);
  const VertexStars stars = vertex_stars(mesh);
  const EdgeCounts total = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, m, 4096), EdgeCounts{},
      [&](const tbb::blocked_range<size_t>& r, EdgeCounts c) {
        for (size_t t = r.begin(); t != r.end(); ++t) triangle_neighbours(mesh, stars, t, c);
        return c;
      },
      [](EdgeCounts x, const EdgeCounts& y) {
        x.add(y);
        return x;
      });
  MeshStats stats = total.stats;
  stats.euler_characteristic = (long long)mesh.vertex_count() - total.edges + (long long)m;
  mesh.stats = stats;
}

void compute_parts(Mesh& mesh) {
  const size_t m = mesh.triangle_count();
  std::vector<int32_t> root(m);
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int32_t x) {
    while (root[size_t(x)] != x) x = root[size_t(x)] = root[size_t(root[size_t(x)])];
    return x;
  };
  for (size_t t = 0; t < m; ++t)
    for (int i = 0; i < 3; ++i) {
      const int32_t u = mesh.neighbours[3 * t + size_t(i)];
      if (u < 0) continue;
      const int32_t a = find(int32_t(t)), b = find(u);
      if (a != b) root[size_t(std::max(a, b))] = std::min(a, b);
    }
  // Number parts by size, largest first; equal sizes by first triangle.
  std::vector<int64_t> size(m, 0);
  for (size_t t = 0; t < m; ++t) ++size[size_t(find(int32_t(t)))];
  std::vector<int32_t> roots;
  for (size_t t = 0; t < m; ++t)
    if (root[t] == int32_t(t)) roots.push_back(int32_t(t));
  std::stable_sort(roots.begin(), roots.end(),
                   [&](int32_t a, int32_t b) { return size[size_t(a)] > size[size_t(b)]; });
  std::vector<int32_t> label(m, -1);
  for (size_t r = 0; r < roots.size(); ++r) label[size_t(roots[r])] = int32_t(r);
  mesh.parts.resize(m);
  for (size_t t = 0; t < m; ++t) mesh.parts[t] = label[size_t(find(int32_t(t)))];
  mesh.part_count = int32_t(roots.size());
}

void compute_topology(Mesh& mesh) {
  compute_neighbours(mesh);
  compute_parts(mesh);
}

}  // namespace isoform
