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

// The area-weighted normal of the triangles around each vertex and each
// vertex's one-ring neighbours.
struct Rings {
  std::vector<Vector3d> area_normal;
  std::vector<std::vector<int32_t>> ring;
};

Rings build_rings(const Mesh& m) {
  Rings r;
  r.area_normal.assign(m.vertex_count(), Vector3d::Zero());
  r.ring.resize(m.vertex_count());
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const int32_t* tri = &m.triangles[3 * t];
    const Vector3d n = (point(m, tri[1]) - point(m, tri[0])).cross(point(m, tri[2]) - point(m, tri[0]));
    for (int i = 0; i < 3; ++i) {
      r.area_normal[size_t(tri[i])] += n;
      r.ring[size_t(tri[i])].push_back(tri[(i + 1) % 3]);
      r.ring[size_t(tri[i])].push_back(tri[(i + 2) % 3]);
    }
  }
  for (auto& ring : r.ring) {
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  }
  return r;
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
  Eigen::MatrixXd a(ring.size(), cols);
  Eigen::VectorXd h(ring.size());
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
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(h);
  if (!c.allFinite()) return n;
  return (n - c(0) * d1 - c(1) * d2).normalized();
}

}  // namespace

void estimate_normals(Mesh& mesh) {
  const Rings r = build_rings(mesh);
  mesh.normals.assign(3 * mesh.vertex_count(), 0.0f);
  tbb::parallel_for(size_t(0), mesh.vertex_count(), [&](size_t v) {
    Vector3d n = r.area_normal[v];
    if (n.norm() == 0 || r.ring[v].size() < 2) {
      n = Vector3d(0, 0, 1);
    } else {
      n.normalize();
      // Two passes: the second fits in the frame the first one found, which
      // brings the height axis closer to the surface normal.
      for (int pass = 0; pass < 2; ++pass) {
        const Vector3d next = fit_normal(mesh, int32_t(v), r.ring[v], n);
        if (next.allFinite() && next.dot(n) > 0) n = next;
      }
    }
    for (int a = 0; a < 3; ++a) mesh.normals[3 * v + a] = float(n[a]);
  });
}

}  // namespace isoform
