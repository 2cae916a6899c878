// Remark 3.15 of Hamann (1991): normals of a triangulation from the
// triangulation alone, by least squares on each vertex's one-ring.
#include "mesh_normals.h"

#include <Eigen/Dense>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

namespace isoform {
namespace {

using Eigen::Vector3d;

Vector3d point(const Mesh& m, int32_t v) {
  return {m.points[3 * size_t(v)], m.points[3 * size_t(v) + 1], m.points[3 * size_t(v) + 2]};
}

// Each vertex's triangles, in increasing id (compressed rows).
struct VertexTriangles {
  std::vector<size_t> start;
  std::vector<int32_t> triangle;
};

VertexTriangles vertex_triangles(const Mesh& m) {
  VertexTriangles r;
  r.start.assign(m.vertex_count() + 1, 0);
  for (int32_t v : m.triangles) ++r.start[size_t(v) + 1];
  for (size_t v = 0; v < m.vertex_count(); ++v) r.start[v + 1] += r.start[v];
  r.triangle.resize(m.triangles.size());
  std::vector<size_t> at(r.start.begin(), r.start.end() - 1);
  for (size_t t = 0; t < m.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) r.triangle[at[size_t(m.triangles[3 * t + size_t(i)])]++] = int32_t(t);
  return r;
}

// The area-weighted normal of vertex v's triangles (summed in the order of
// their ids) and v's one-ring neighbours, sorted.
Vector3d area_normal_and_ring(const Mesh& m, const VertexTriangles& vt, size_t v, std::vector<int32_t>& ring) {
  Vector3d sum = Vector3d::Zero();
  ring.clear();
  for (size_t k = vt.start[v]; k < vt.start[v + 1]; ++k) {
    if (k > vt.start[v] && vt.triangle[k] == vt.triangle[k - 1]) continue;  // v twice in it: once per corner below
    const int32_t* tri = &m.triangles[3 * size_t(vt.triangle[k])];
    const Vector3d n = (point(m, tri[1]) - point(m, tri[0])).cross(point(m, tri[2]) - point(m, tri[0]));
    for (int i = 0; i < 3; ++i) {
      if (tri[i] != int32_t(v)) continue;
      sum += n;
      ring.push_back(tri[(i + 1) % 3]);
      ring.push_back(tri[(i + 2) % 3]);
    }
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  return sum;
}

// One fit in the frame whose height axis is n: heights d_j over the plane,
// quadratic when seven or more neighbours over-determine its five
// coefficients (fewer make it chase noise), else a plane through the
// vertex. Returns the graph's normal at the vertex (Remark 3.15).
Vector3d fit_normal(const Mesh& m, int32_t v, const std::vector<int32_t>& ring, const Vector3d& n) {
  const Vector3d d1 = n.unitOrthogonal(), d2 = n.cross(d1);
  const Vector3d o = point(m, v);
  const bool quadratic = ring.size() >= 7;
  const int cols = quadratic ? 5 : 2;
  // NOTE: the matrices and the factorisation kept per thread: they keep
  // their storage while the sizes repeat (most vertices have the same
  // degree), where new ones allocated several times per vertex.
  static thread_local Eigen::MatrixXd a;
  static thread_local Eigen::VectorXd h, c;
  static thread_local Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
  a.resize(Eigen::Index(ring.size()), cols);
  h.resize(Eigen::Index(ring.size()));
  for (size_t j = 0; j < ring.size(); ++j) {
    const Vector3d p = point(m, ring[j]) - o;
    const double x = p.dot(d1), y = p.dot(d2);
    // The fit passes through the vertex itself (no constant term).
    a(Eigen::Index(j), 0) = x;
    a(Eigen::Index(j), 1) = y;
    if (quadratic) {
      a(Eigen::Index(j), 2) = x * x;
      a(Eigen::Index(j), 3) = x * y;
      a(Eigen::Index(j), 4) = y * y;
    }
    h(Eigen::Index(j)) = p.dot(n);
  }
  qr.compute(a);
  c = qr.solve(h);
  if (!c.allFinite()) return n;
  return (n - c(0) * d1 - c(1) * d2).normalized();
}

}  // namespace

// NOTE: each vertex gathers its own triangles and ring, in parallel, from
// one table of every vertex's triangles (one vector per vertex, filled
// serially, was most of the time on a million triangles).
void estimate_normals(Mesh& mesh) {
  const VertexTriangles vt = vertex_triangles(mesh);
  mesh.normals.assign(3 * mesh.vertex_count(), 0.0f);
  tbb::parallel_for(size_t(0), mesh.vertex_count(), [&](size_t v) {
    static thread_local std::vector<int32_t> ring;
    Vector3d n = area_normal_and_ring(mesh, vt, v, ring);
    if (n.norm() == 0 || ring.size() < 2) {
      n = Vector3d(0, 0, 1);
    } else {
      n.normalize();
      // Two passes: the second fits in the frame the first one found, which
      // brings the height axis closer to the surface normal.
      for (int pass = 0; pass < 2; ++pass) {
        const Vector3d next = fit_normal(mesh, int32_t(v), ring, n);
        if (next.allFinite() && next.dot(n) > 0) n = next;
      }
    }
    for (int a = 0; a < 3; ++a) mesh.normals[3 * v + a] = float(n[a]);
  });
}

}  // namespace isoform
