// Remark 3.15 of Hamann (1991): normals of a triangulation from the
// triangulation alone, by least squares on each vertex's one-ring.
#include "mesh_normals.h"

#include <Eigen/Dense>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "curvature/height_fit.h"

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

// The plane h = c0 x + c1 y by its 2 x 2 normal equations in coordinates
// scaled by the largest |(x, y)|; false where they are not well conditioned.
bool plane_by_normal_equations(const double* x, const double* y, const double* h, int count, double min_rcond,
                               double& c0, double& c1) {
  double r2 = 0.0;
  for (int j = 0; j < count; ++j) r2 = std::max(r2, x[j] * x[j] + y[j] * y[j]);
  const double scale = std::sqrt(r2);
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  const double inv = 1.0 / scale;
  double sxx = 0, sxy = 0, syy = 0, sxh = 0, syh = 0;
  for (int j = 0; j < count; ++j) {
    const double u = x[j] * inv, v = y[j] * inv;
    sxx += u * u;
    sxy += u * v;
    syy += v * v;
    sxh += u * h[j];
    syh += v * h[j];
  }
  if (!(sxx > 0.0)) return false;
  const double l = sxy / sxx, d1 = syy - l * sxy;
  if (!(d1 > 0.0) || std::min(sxx, d1) < min_rcond * std::max(sxx, d1)) return false;
  const double b1 = (syh - l * sxh) / d1;
  const double b0 = sxh / sxx - l * b1;
  c0 = b0 * inv;
  c1 = b1 * inv;
  return std::isfinite(c0) && std::isfinite(c1);
}

// One fit in the frame whose height axis is n: heights d_j over the plane,
// quadratic when seven or more neighbours over-determine its five
// coefficients (fewer make it chase noise), else a plane through the
// vertex. Returns the graph's normal at the vertex (Remark 3.15).
// NOTE: the least-squares problem is solved by its normal equations in
// scaled coordinates (fit_height's quadric, or the plane's 2 x 2), which
// give the QR's solution to far below a float's precision where they are
// well conditioned (smallest over largest pivot at least 1e-8) and cost a
// fraction of a dynamic-size QR; elsewhere a column-pivoting QR solves it.
Vector3d fit_normal(const Mesh& m, int32_t v, const std::vector<int32_t>& ring, const Vector3d& n) {
  constexpr double kMinRcond = 1e-8;
  const Vector3d d1 = n.unitOrthogonal(), d2 = n.cross(d1);
  const Vector3d o = point(m, v);
  const bool quadratic = ring.size() >= 7;
  const int cols = quadratic ? 5 : 2;
  const int count = int(ring.size());
  static thread_local std::vector<double> xyh;
  xyh.resize(3 * ring.size());
  double *x = xyh.data(), *y = x + count, *h = y + count;
  for (int j = 0; j < count; ++j) {
    const Vector3d p = point(m, ring[size_t(j)]) - o;
    x[j] = p.dot(d1);
    y[j] = p.dot(d2);
    h[j] = p.dot(n);
  }
  double c0 = 0, c1 = 0;
  bool solved = false;
  if (quadratic) {
    const HeightFit fit = fit_height(FitModel::Quadric, x, y, h, count, kMinRcond);
    if (fit.ok) {
      c0 = fit.fu;
      c1 = fit.fv;
      solved = true;
    }
  } else {
    solved = plane_by_normal_equations(x, y, h, count, kMinRcond, c0, c1);
  }
  if (!solved) {
    // NOTE: the matrices and the factorisation kept per thread: they keep
    // their storage while the sizes repeat.
    static thread_local Eigen::MatrixXd a;
    static thread_local Eigen::VectorXd rhs, c;
    static thread_local Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
    a.resize(Eigen::Index(count), cols);
    rhs.resize(Eigen::Index(count));
    for (int j = 0; j < count; ++j) {
      // The fit passes through the vertex itself (no constant term).
      a(j, 0) = x[j];
      a(j, 1) = y[j];
      if (quadratic) {
        a(j, 2) = x[j] * x[j];
        a(j, 3) = x[j] * y[j];
        a(j, 4) = y[j] * y[j];
      }
      rhs(j) = h[j];
    }
    qr.compute(a);
    c = qr.solve(rhs);
    if (!c.allFinite()) return n;
    c0 = c(0);
    c1 = c(1);
  }
  return (n - c0 * d1 - c1 * d2).normalized();
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
