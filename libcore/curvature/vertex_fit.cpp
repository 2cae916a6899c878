// One vertex of Section 4.2: frame from the normal (steps ii, iii), local
// coordinates and heights of the platelet points (iv to vi, 4.24 to 4.27),
// the fit (vii) and Theorem 4.3 (viii), with the fallbacks the seed lacks.
#include "vertex_fit.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>

namespace isoform {
namespace {

using Eigen::Vector3d;

Vector3d point(const Mesh& m, int32_t v) {
  if (m.precise_points.size() == m.points.size()) {
    const double* p = &m.precise_points[3 * size_t(v)];
    return {p[0], p[1], p[2]};
  }
  const float* p = &m.points[3 * size_t(v)];
  return {p[0], p[1], p[2]};
}

// The model and rings of each method. A fit of degree d needs d + 1
// distinct positions along every direction: a two-ring gives five around an
// interior vertex, but a boundary vertex sees only one side, so it takes
// rings enough for d + 1 there. The quartic takes the three-ring inside:
// with two rings it interpolates nearly, and on contour meshes, whose
// vertices carry the interpolation error of Chapter 3, its error was 12% of
// 1/r on spheres against 3% with three rings (docs/curvature-surface.md).
struct Plan {
  FitModel model;
  int rings;
  int boundary_rings;
};

Plan plan_of(CurvatureMethod method) {
  switch (method) {
    case CurvatureMethod::Seed: return {FitModel::SeedQuadratic, 1, 1};
    case CurvatureMethod::Quadric: return {FitModel::Quadric, 1, 2};
    case CurvatureMethod::Cubic: return {FitModel::Cubic, 2, 3};
    case CurvatureMethod::Quartic: return {FitModel::Quartic, 3, 5};
  }
  return {FitModel::Quartic, 3, 5};
}

FitModel lower(FitModel m) {
  switch (m) {
    case FitModel::Quartic: return FitModel::Cubic;
    case FitModel::Cubic: return FitModel::Quadric;
    default: return FitModel::SeedQuadratic;
  }
}

// Points beyond the exact count of terms that a model wants before its fit
// is trusted: least squares, not interpolation, except for the seed's fit,
// which (4.29) solves with as few as three points.
int points_wanted(FitModel m) {
  const int t = fit_terms(m);
  return m == FitModel::SeedQuadratic ? t : t + (t + 3) / 4;
}

// The normal the frame is built on: the mesh's own where usable, else the
// smallest principal axis of the platelet (whose sign is then arbitrary: the
// vertex is flagged).
bool frame_normal(const Mesh& mesh, int32_t v, const std::vector<int32_t>& near, Vector3d& n) {
  if (mesh.normals.size() == mesh.points.size()) {
    const float* q = &mesh.normals[3 * size_t(v)];
    n = {q[0], q[1], q[2]};
    const double len = n.norm();
    if (std::isfinite(len) && len > 0.5) {
      n /= len;
      return true;
    }
  }
  const Vector3d o = point(mesh, v);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int32_t w : near) {
    const Vector3d p = point(mesh, w) - o;
    cov += p * p.transpose();
  }
  n = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
  return false;
}

// Local coordinates (4.27) and signed heights (4.24) of the gathered points;
// points that coincide with the vertex carry nothing and are left out.
void local_coordinates(const Mesh& mesh, int32_t v, const std::vector<int32_t>& near, const Vector3d& b1,
                       const Vector3d& b2, const Vector3d& n, VertexFitScratch& s) {
  const Vector3d o = point(mesh, v);
  s.u.clear();
  s.v.clear();
  s.d.clear();
  for (int32_t w : near) {
    const Vector3d p = point(mesh, w) - o;
    const double u = p.dot(b1), vv = p.dot(b2);
    if (u == 0.0 && vv == 0.0) continue;
    s.u.push_back(u);
    s.v.push_back(vv);
    s.d.push_back(p.dot(n));
  }
}

}  // namespace

VertexFitResult fit_vertex(const Mesh& mesh, const VertexRings& rings, int32_t v, CurvatureMethod method,
                           int extra_rings, VertexFitScratch& s) {
  VertexFitResult r;
  if (rings.valence(v) == 0) {
    r.flags = kCurvatureIsolated;
    return r;
  }
  if (rings.nonmanifold(v)) r.flags |= kCurvatureNonmanifold;
  Plan plan = plan_of(method);
  plan.rings += extra_rings;
  plan.boundary_rings += extra_rings;
  // The seed's method is kept as printed: no boundary treatment.
  if (rings.on_boundary(v) && method != CurvatureMethod::Seed) {
    r.flags |= kCurvatureBoundary;
    plan.rings = plan.boundary_rings;
  }
  const int widest = plan.rings + 2;
  Vector3d n;
  gather_rings(rings, v, plan.rings, s.rings);
  if (!frame_normal(mesh, v, s.rings.out, n)) r.flags |= kCurvatureNormalRepaired;
  const Vector3d b1 = n.unitOrthogonal(), b2 = n.cross(b1);
  FitModel model = plan.model;
  int ring_count = plan.rings;
  for (;;) {
    local_coordinates(mesh, v, s.rings.out, b1, b2, n, s);
    const int count = int(s.u.size());
    if (count >= points_wanted(model)) {
      const HeightFit fit = fit_height(model, s.u.data(), s.v.data(), s.d.data(), count);
      if (fit.ok) {
        r.curvature = principal_curvatures(fit, b1, b2, n);
        return r;
      }
    }
    if (ring_count < widest) {
      const size_t before = s.rings.out.size();
      gather_rings(rings, v, ++ring_count, s.rings);
      if (s.rings.out.size() > before) {
        r.flags |= kCurvatureWidened;
        continue;
      }
    }
    if (model != FitModel::SeedQuadratic) {
      model = lower(model);
      r.flags |= kCurvatureLowerOrder;
    } else {
      r.flags |= kCurvatureFailed;
      r.curvature = PrincipalCurvatures{};
      r.curvature.normal = n;
      r.curvature.d1 = b1;
      r.curvature.d2 = b2;
      return r;
    }
  }
}

}  // namespace isoform
