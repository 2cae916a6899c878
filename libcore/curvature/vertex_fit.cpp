// One vertex of Section 4.2: frame from the normal (steps ii, iii), local
// coordinates and heights of the platelet points (iv to vi, 4.24 to 4.27),
// the fit (vii) and Theorem 4.3 (viii), with the fallbacks the seed lacks.
#include "vertex_fit.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>

#include "ring_coordinates.h"

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
// s's arrays get one entry to spare: the last point is written before it is
// known whether it stays.
template <class Real>
int local_coordinates(const Real* points, int32_t v, const std::vector<int32_t>& near, const Vector3d& b1,
                      const Vector3d& b2, const Vector3d& n, PlateletPoints& s) {
  if (s.u.size() < near.size() + 1) {
    s.u.resize(near.size() + 1);
    s.v.resize(near.size() + 1);
    s.d.resize(near.size() + 1);
  }
  return ring_coordinates(points, v, near.data(), near.data() + near.size(), b1, b2, n, s.u.data(), s.v.data(),
                          s.d.data());
}

int local_coordinates(const Mesh& mesh, int32_t v, const std::vector<int32_t>& near, const Vector3d& b1,
                      const Vector3d& b2, const Vector3d& n, PlateletPoints& s) {
  if (mesh.precise_points.size() == mesh.points.size())
    return local_coordinates(mesh.precise_points.data(), v, near, b1, b2, n, s);
  return local_coordinates(mesh.points.data(), v, near, b1, b2, n, s);
}

// Steps (i) to (iii) of one vertex: its flags, plan and frame, the platelet
// gathered into scratch.rings.out. False for an isolated vertex (r is then
// its result).
struct Start {
  Plan plan;
  Vector3d n, b1, b2;
};

bool start_vertex(const Mesh& mesh, const VertexRings& rings, int32_t v, CurvatureMethod method, int extra_rings,
                  VertexFitScratch& s, VertexFitResult& r, Start& st) {
  if (rings.valence(v) == 0) {
    r.flags = kCurvatureIsolated;
    return false;
  }
  if (rings.nonmanifold(v)) r.flags |= kCurvatureNonmanifold;
  st.plan = plan_of(method);
  st.plan.rings += extra_rings;
  st.plan.boundary_rings += extra_rings;
  // The seed's method is kept as printed: no boundary treatment.
  if (rings.on_boundary(v) && method != CurvatureMethod::Seed) {
    r.flags |= kCurvatureBoundary;
    st.plan.rings = st.plan.boundary_rings;
  }
  gather_rings(rings, v, st.plan.rings, s.rings);
  if (!frame_normal(mesh, v, s.rings.out, st.n)) r.flags |= kCurvatureNormalRepaired;
  st.b1 = st.n.unitOrthogonal();
  st.b2 = st.n.cross(st.b1);
  return true;
}

}  // namespace

VertexFitResult fit_vertex(const Mesh& mesh, const VertexRings& rings, int32_t v, CurvatureMethod method,
                           int extra_rings, VertexFitScratch& s) {
  VertexFitResult r;
  Start st;
  if (!start_vertex(mesh, rings, v, method, extra_rings, s, r, st)) return r;
  const Vector3d &n = st.n, &b1 = st.b1, &b2 = st.b2;
  const int widest = st.plan.rings + 2;
  FitModel model = st.plan.model;
  int ring_count = st.plan.rings;
  for (;;) {
    const int count = local_coordinates(mesh, v, s.rings.out, b1, b2, n, s.points);
    if (count >= points_wanted(model)) {
      const HeightFit fit = fit_height(model, s.points.u.data(), s.points.v.data(), s.points.d.data(), count);
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

void fit_vertices(const Mesh& mesh, const VertexRings& rings, int32_t first, int count, CurvatureMethod method,
                  int extra_rings, VertexFitScratch& s, VertexFitResult (&out)[4]) {
  // Lane k of the side-by-side fit holds vertex first + vertex_of[k].
  Start st[4];
  int vertex_of[4], lanes = 0;
  const double* u[4] = {};
  const double* v[4] = {};
  const double* d[4] = {};
  int points[4] = {0, 0, 0, 0};
  bool alone[4] = {false, false, false, false};
  const FitModel model = plan_of(method).model;
  for (int i = 0; i < count; ++i) {
    const int32_t vertex = first + i;
    out[i] = VertexFitResult{};
    if (!start_vertex(mesh, rings, vertex, method, extra_rings, s, out[i], st[i])) continue;
    PlateletPoints& p = s.lanes[lanes];
    const int m = local_coordinates(mesh, vertex, s.rings.out, st[i].b1, st[i].b2, st[i].n, p);
    if (m < points_wanted(model)) {
      alone[i] = true;
      continue;
    }
    u[lanes] = p.u.data();
    v[lanes] = p.v.data();
    d[lanes] = p.d.data();
    points[lanes] = m;
    vertex_of[lanes++] = i;
  }
  if (lanes > 0) {
    HeightFit fit[4];
    fit_height_lanes(model, u, v, d, points, lanes, fit);
    for (int k = 0; k < lanes; ++k) {
      const int i = vertex_of[k];
      if (fit[k].ok)
        out[i].curvature = principal_curvatures(fit[k], st[i].b1, st[i].b2, st[i].n);
      else
        alone[i] = true;
    }
  }
  // What the first fit could not settle: fit_vertex from the start (its
  // first fit fails the same way, and it goes on from there).
  for (int i = 0; i < count; ++i)
    if (alone[i]) out[i] = fit_vertex(mesh, rings, first + i, method, extra_rings, s);
}

}  // namespace isoform
