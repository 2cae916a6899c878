// One vertex of Section 4.2: frame from the normal (steps ii, iii), local
// coordinates and heights of the platelet points (iv to vi, 4.24 to 4.27),
// the fit (vii) and Theorem 4.3 (viii), with the fallbacks the seed lacks.
#include "vertex_fit.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <utility>

#include "principal_lanes.h"
#include "ring_coordinates.h"
#include "vector_level.h"

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
bool frame_normal(const Mesh& mesh, int32_t v, const RingList& near, Vector3d& n) {
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

// Local coordinates (4.27) and signed heights (4.24) of the gathered points
// into u, v, d at entries 0, Stride, 2 Stride, ... (ring_coordinates.h);
// points that coincide with the vertex carry nothing and are left out. The
// arrays need room for one point more than `near` holds.
template <int Stride>
int local_coordinates(const Mesh& mesh, int32_t v, const RingList& near, const Vector3d& b1,
                      const Vector3d& b2, const Vector3d& n, double* u, double* w, double* d) {
  const int32_t *first = near.data(), *last = near.data() + near.size();
  if (mesh.precise_points.size() == mesh.points.size())
    return ring_coordinates<Stride>(mesh.precise_points.data(), v, first, last, b1, b2, n, u, w, d);
  return ring_coordinates<Stride>(mesh.points.data(), v, first, last, b1, b2, n, u, w, d);
}

// The same into s's arrays, one point after another.
int local_coordinates(const Mesh& mesh, int32_t v, const RingList& near, const Vector3d& b1,
                      const Vector3d& b2, const Vector3d& n, PlateletPoints& s) {
  if (s.u.size() < near.size() + 1) {
    s.u.resize(near.size() + 1);
    s.v.resize(near.size() + 1);
    s.d.resize(near.size() + 1);
  }
  return local_coordinates<1>(mesh, v, near, b1, b2, n, s.u.data(), s.v.data(), s.d.data());
}

// Steps (i) to (iii) of one vertex: its flags, plan and frame, the platelet
// gathered into scratch.rings.out. False for an isolated vertex (r is then
// its result).
struct Start {
  Plan plan;
  Vector3d n, b1, b2;
};

bool start_vertex(const Mesh& mesh, const VertexRings& rings, int32_t v, CurvatureMethod method, int extra_rings,
                  VertexFitScratch& s, VertexFitResult& r, Start& st, bool tangents = true) {
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
  if (tangents) {  // else the caller finds b1, b2 (frame_lanes gives the same bits)
    st.b1 = st.n.unitOrthogonal();
    st.b2 = st.n.cross(st.b1);
  }
  return true;
}

// ring_coordinates_lanes on the mesh's points, in the frames (b1, b2, n) of
// the four lanes; built for AVX too and chosen at run time (vector_level.h).
ISOFORM_LANES_INLINE int coordinates_body(const Mesh& mesh, const int32_t (&vertex)[4],
                                          const int32_t* const (&ring)[4], const int (&valence)[4],
                                          const Vector3d (&b1)[4], const Vector3d (&b2)[4], const Vector3d (&n)[4],
                                          PlateletPoints& p, bool (&coincide)[4]) {
  const Vec3Lanes e1 = vec3_lanes(b1), e2 = vec3_lanes(b2), e3 = vec3_lanes(n);
  if (mesh.precise_points.size() == mesh.points.size())
    return ring_coordinates_lanes(mesh.precise_points.data(), vertex, ring, valence, e1, e2, e3, p.u.data(),
                                  p.v.data(), p.d.data(), coincide);
  return ring_coordinates_lanes(mesh.points.data(), vertex, ring, valence, e1, e2, e3, p.u.data(), p.v.data(),
                                p.d.data(), coincide);
}

int coordinates_plain(const Mesh& mesh, const int32_t (&vertex)[4], const int32_t* const (&ring)[4],
                      const int (&valence)[4], const Vector3d (&b1)[4], const Vector3d (&b2)[4],
                      const Vector3d (&n)[4], PlateletPoints& p, bool (&coincide)[4]) {
  return coordinates_body(mesh, vertex, ring, valence, b1, b2, n, p, coincide);
}

#ifdef ISOFORM_AVX_CLONE
ISOFORM_AVX_TARGET int coordinates_avx(const Mesh& mesh, const int32_t (&vertex)[4], const int32_t* const (&ring)[4],
                                       const int (&valence)[4], const Vector3d (&b1)[4], const Vector3d (&b2)[4],
                                       const Vector3d (&n)[4], PlateletPoints& p, bool (&coincide)[4]) {
  return coordinates_body(mesh, vertex, ring, valence, b1, b2, n, p, coincide);
}
#endif

int coordinates_lanes(const Mesh& mesh, const int32_t (&vertex)[4], const int32_t* const (&ring)[4],
                      const int (&valence)[4], const Vector3d (&b1)[4], const Vector3d (&b2)[4],
                      const Vector3d (&n)[4], PlateletPoints& p, bool (&coincide)[4]) {
#ifdef ISOFORM_AVX_CLONE
  if (vector_level() > 0) return coordinates_avx(mesh, vertex, ring, valence, b1, b2, n, p, coincide);
#endif
  return coordinates_plain(mesh, vertex, ring, valence, b1, b2, n, p, coincide);
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
  // Vertex first + l in lane l of the side-by-side fit: its platelet's
  // points at 4 j + l of s.lanes (fit_height_lanes' layout). Unused lanes
  // get no points and a plain frame.
  Start st[4];
  int32_t vertex[4];
  const int32_t* ring[4] = {};
  int valence[4] = {0, 0, 0, 0}, points[4] = {0, 0, 0, 0};
  bool alone[4] = {false, false, false, false};
  Vector3d b1[4], b2[4], n[4];
  const FitModel model = plan_of(method).model;
  const int wanted = points_wanted(model);
  for (int l = 0; l < 4; ++l) {
    vertex[l] = first + std::min(l, count - 1);
    b1[l] = Vector3d::UnitX();
    b2[l] = Vector3d::UnitY();
    n[l] = Vector3d::UnitZ();
    if (l >= count) continue;
    out[l] = VertexFitResult{};
    if (!start_vertex(mesh, rings, vertex[l], method, extra_rings, s, out[l], st[l], false)) continue;
    // Fewer neighbours than the model wants: fewer points too.
    if (s.rings.out.size() < size_t(wanted)) {
      alone[l] = true;
      continue;
    }
    std::swap(s.lane_rings[l], s.rings.out);  // the platelet moves to its lane, no copy
    ring[l] = s.lane_rings[l].data();
    valence[l] = int(s.lane_rings[l].size());
    n[l] = st[l].n;
  }
  // The tangents of the lanes with points, four at a time.
  {
    Vec3Lanes e1, e2;
    frame_lanes(vec3_lanes(n), e1, e2);
    for (int l = 0; l < 4; ++l)
      if (valence[l] > 0) {
        b1[l] = {e1.x[l], e1.y[l], e1.z[l]};
        b2[l] = {e2.x[l], e2.y[l], e2.z[l]};
      }
  }
  const int widest = std::max(std::max(valence[0], valence[1]), std::max(valence[2], valence[3]));
  if (widest == 0) {
    for (int l = 0; l < count; ++l)
      if (alone[l]) out[l] = fit_vertex(mesh, rings, first + l, method, extra_rings, s);
    return;
  }
  PlateletPoints& p = s.lanes;
  const size_t room = 4 * (size_t(widest) + 1);
  if (p.u.size() < room) {
    p.u.resize(room);
    p.v.resize(room);
    p.d.resize(room);
  }
  bool coincide[4];
  coordinates_lanes(mesh, vertex, ring, valence, b1, b2, n, p, coincide);
  for (int l = 0; l < 4; ++l) {
    if (valence[l] == 0) continue;
    // A neighbour on the vertex: its lane again, one point after another,
    // with that point left out.
    const int m = coincide[l] ? local_coordinates<4>(mesh, vertex[l], s.lane_rings[l], b1[l], b2[l], n[l],
                                                     p.u.data() + l, p.v.data() + l, p.d.data() + l)
                              : valence[l];
    if (m < wanted)
      alone[l] = true;
    else
      points[l] = m;
    for (int j = points[l]; j < widest; ++j)
      p.u[4 * size_t(j) + size_t(l)] = p.v[4 * size_t(j) + size_t(l)] = p.d[4 * size_t(j) + size_t(l)] = 0.0;
  }
  HeightFit fit[4];
  fit_height_lanes(model, p.u.data(), p.v.data(), p.d.data(), points, fit);
  for (int l = 0; l < 4; ++l) {
    if (points[l] > 0 && !fit[l].ok) alone[l] = true;
    if (points[l] == 0 || !fit[l].ok) {  // a lane computed for nothing: zeros and a plain frame
      fit[l] = HeightFit{};
      b1[l] = Vector3d::UnitX();
      b2[l] = Vector3d::UnitY();
      n[l] = Vector3d::UnitZ();
    }
  }
  PrincipalCurvatures pc[4];
  principal_curvatures4(fit, b1, b2, n, pc);
  for (int l = 0; l < count; ++l) {
    if (alone[l])
      // What the first fit could not settle: fit_vertex from the start
      // (its first fit fails the same way, and it goes on from there).
      out[l] = fit_vertex(mesh, rings, first + l, method, extra_rings, s);
    else if (points[l] > 0)
      out[l].curvature = pc[l];
  }
}

}  // namespace isoform
