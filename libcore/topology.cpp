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

}  // namespace

bool is_degenerate_triangle(const Mesh& mesh, size_t t) {
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

namespace {

bool degenerate(const Mesh& mesh, size_t t) { return is_degenerate_triangle(mesh, t); }

// What one stretch of vertices finds: the stats' counts and the edges whose
// lowest triangle it decided.
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

// A triangle around a vertex, with its corners, read once per vertex.
struct StarTriangle {
  int32_t id;
  int32_t v[3];
};

// Records what triangle t's edge i, from a to b, found around a: count
// other triangles hold b, the last of them `other`; none of them comes
// before t (lowest); one of them runs the edge from a to b too.
void record_edge(Mesh& mesh, size_t t, int i, int count, int32_t other, bool lowest, bool same_direction,
                 EdgeCounts& c) {
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

// The edges from vertex a to the corner after it, of every triangle around
// a (star: a's triangles, gathered): their neighbours into mesh.neighbours,
// their counts into c; and each triangle's degeneracy at its first corner.
void vertex_edges(Mesh& mesh, int32_t a, const std::vector<StarTriangle>& star, EdgeCounts& c) {
  for (size_t k = 0; k < star.size(); ++k) {
    if (k > 0 && star[k].id == star[k - 1].id) continue;  // a triangle with a twice is listed twice
    const size_t t = size_t(star[k].id);
    const int32_t* tri = star[k].v;
    if (tri[0] == a) c.stats.degenerate_triangles += degenerate(mesh, t);
    for (int i = 0; i < 3; ++i) {
      if (tri[i] != a) continue;
      const int32_t b = tri[(i + 1) % 3];
      // Every triangle around a that also holds b shares the edge (a, b).
      int count = 0;
      int32_t other = -1;
      bool same_direction = false, lowest = true;
      for (const StarTriangle& s : star) {
        const int32_t u = s.id;
        if (size_t(u) == t) continue;
        const int cb = corner_of(s.v, b);
        if (cb < 0) continue;
        ++count;
        other = u;
        if (size_t(u) < t) lowest = false;
        // A consistent neighbour runs the edge from b to a; one that runs it
        // from a to b (a just before b) is inconsistently oriented.
        if (s.v[(cb + 2) % 3] == a) same_direction = true;
      }
      record_edge(mesh, t, i, count, other, lowest, same_direction, c);
    }
  }
}

// The corners after and before a vertex in one of its triangles.
struct StarSides {
  int32_t id, next, prev;
  int corner;  // the vertex's
};

// vertex_edges where no triangle around a repeats a corner: a's corner is
// then unique in each, and b is in a triangle exactly when it is the corner
// after or before a there (after: the same direction as t).
// NOTE: without branches on the corners (a vertex's edges met its
// triangles' corners in an order no branch predictor learns).
void plain_vertex_edges(Mesh& mesh, const std::vector<StarSides>& star, EdgeCounts& c) {
  for (const StarSides& e : star) {
    const int32_t t = e.id, b = e.next;
    int count = 0;
    int32_t other = -1;
    bool same_direction = false, lowest = true;
    for (const StarSides& s : star) {
      const int after = s.next == b, elsewhere = s.id != t, hit = (after | int(s.prev == b)) & elsewhere;
      count += hit;
      other = hit ? s.id : other;
      lowest &= !(hit & int(s.id < t));
      same_direction |= bool(after & elsewhere);
    }
    record_edge(mesh, size_t(t), e.corner, count, other, lowest, same_direction, c);
  }
}

}  // namespace

// NOTE: every edge (a, b) of a triangle is decided around a, from a's
// triangles copied side by side once (each triangle is read three times,
// not once per edge and triangle around the edge's first corner); the
// vertices go side by side, each writing its own edges' neighbours and
// counting into its stretch's sums, the same for any split.
void compute_neighbours(Mesh& mesh) {
  const size_t m = mesh.triangle_count(), nv = mesh.vertex_count();
  mesh.neighbours.assign(3 * m, -1);
  const VertexStars stars = vertex_stars(mesh);
  const EdgeCounts total = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, nv, 2048), EdgeCounts{},
      [&](const tbb::blocked_range<size_t>& r, EdgeCounts c) {
        std::vector<StarTriangle> star;
        std::vector<StarSides> sides;
        for (size_t a = r.begin(); a != r.end(); ++a) {
          star.clear();
          sides.clear();
          bool plain = true;
          for (const int32_t* u = stars.begin(a); u != stars.end(a); ++u) {
            const int32_t* tri = &mesh.triangles[3 * size_t(*u)];
            star.push_back({*u, {tri[0], tri[1], tri[2]}});
            plain &= tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2];
            const int k = tri[0] == int32_t(a) ? 0 : tri[1] == int32_t(a) ? 1 : 2;
            sides.push_back({*u, tri[(k + 1) % 3], tri[(k + 2) % 3], k});
          }
          if (plain) {
            for (const StarSides& e : sides)
              if (e.corner == 0) c.stats.degenerate_triangles += degenerate(mesh, size_t(e.id));
            plain_vertex_edges(mesh, sides, c);
          } else {
            vertex_edges(mesh, int32_t(a), star, c);
          }
        }
        return c;
      },
      [](EdgeCounts x, const EdgeCounts& y) {
        x.add(y);
        return x;
      });
  MeshStats stats = total.stats;
  stats.euler_characteristic = (long long)nv - total.edges + (long long)m;
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
