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

namespace {

// One group of four lanes of fit_vertices: vertex first + l in lane l, its
// platelet's points at 4 j + l of its PlateletPoints (fit_height_lanes'
// layout). Unused lanes get no points and a plain frame.
struct LaneGroupState {
  Start st[4];
  int32_t vertex[4];
  const int32_t* ring[4] = {};
  int valence[4] = {0, 0, 0, 0}, points[4] = {0, 0, 0, 0};
  bool alone[4] = {false, false, false, false};
  Vector3d b1[4], b2[4], n[4];
};

// Steps (i) to (iii) of the group's vertices and their tangents, four at a
// time; the widest platelet.
int start_group(const Mesh& mesh, const VertexRings& rings, int32_t first, int count, CurvatureMethod method,
                int extra_rings, int wanted, VertexFitScratch& s, RingList (&lane_rings)[4], LaneGroupState& g,
                VertexFitResult* out) {
  for (int l = 0; l < 4; ++l) {
    g.vertex[l] = first + std::min(l, count - 1);
    g.b1[l] = Vector3d::UnitX();
    g.b2[l] = Vector3d::UnitY();
    g.n[l] = Vector3d::UnitZ();
    if (l >= count) continue;
    out[l] = VertexFitResult{};
    if (!start_vertex(mesh, rings, g.vertex[l], method, extra_rings, s, out[l], g.st[l], false)) continue;
    // Fewer neighbours than the model wants: fewer points too.
    if (s.rings.out.size() < size_t(wanted)) {
      g.alone[l] = true;
      continue;
    }
    std::swap(lane_rings[l], s.rings.out);  // the platelet moves to its lane, no copy
    g.ring[l] = lane_rings[l].data();
    g.valence[l] = int(lane_rings[l].size());
    g.n[l] = g.st[l].n;
  }
  Vec3Lanes e1, e2;
  frame_lanes(vec3_lanes(g.n), e1, e2);
  for (int l = 0; l < 4; ++l)
    if (g.valence[l] > 0) {
      g.b1[l] = {e1.x[l], e1.y[l], e1.z[l]};
      g.b2[l] = {e2.x[l], e2.y[l], e2.z[l]};
    }
  return std::max(std::max(g.valence[0], g.valence[1]), std::max(g.valence[2], g.valence[3]));
}

// Steps (iv) to (vi) of the group's lanes into p, every lane padded with
// zeros up to `widest` points.
void group_coordinates(const Mesh& mesh, int wanted, int widest, const RingList (&lane_rings)[4],
                       LaneGroupState& g, PlateletPoints& p) {
  const size_t room = 4 * (size_t(widest) + 1);
  if (p.u.size() < room) {
    p.u.resize(room);
    p.v.resize(room);
    p.d.resize(room);
  }
  bool coincide[4] = {false, false, false, false};
  if (std::max(std::max(g.valence[0], g.valence[1]), std::max(g.valence[2], g.valence[3])) > 0)
    coordinates_lanes(mesh, g.vertex, g.ring, g.valence, g.b1, g.b2, g.n, p, coincide);
  for (int l = 0; l < 4; ++l) {
    if (g.valence[l] > 0) {
      // A neighbour on the vertex: its lane again, one point after another,
      // with that point left out.
      const int m = coincide[l] ? local_coordinates<4>(mesh, g.vertex[l], lane_rings[l], g.b1[l], g.b2[l], g.n[l],
                                                       p.u.data() + l, p.v.data() + l, p.d.data() + l)
                                : g.valence[l];
      if (m < wanted)
        g.alone[l] = true;
      else
        g.points[l] = m;
    }
    for (int j = g.points[l]; j < widest; ++j)
      p.u[4 * size_t(j) + size_t(l)] = p.v[4 * size_t(j) + size_t(l)] = p.d[4 * size_t(j) + size_t(l)] = 0.0;
  }
}

// Step (viii) of the group's fitted lanes; the rest through fit_vertex.
void finish_group(const Mesh& mesh, const VertexRings& rings, int32_t first, int count, CurvatureMethod method,
                  int extra_rings, VertexFitScratch& s, LaneGroupState& g, HeightFit (&fit)[4],
                  VertexFitResult* out) {
  for (int l = 0; l < 4; ++l) {
    if (g.points[l] > 0 && !fit[l].ok) g.alone[l] = true;
    if (g.points[l] == 0 || !fit[l].ok) {  // a lane computed for nothing: zeros and a plain frame
      fit[l] = HeightFit{};
      g.b1[l] = Vector3d::UnitX();
      g.b2[l] = Vector3d::UnitY();
      g.n[l] = Vector3d::UnitZ();
    }
  }
  PrincipalCurvatures pc[4];
  principal_curvatures4(fit, g.b1, g.b2, g.n, pc);
  for (int l = 0; l < count; ++l) {
    if (g.alone[l])
      // What the first fit could not settle: fit_vertex from the start
      // (its first fit fails the same way, and it goes on from there).
      out[l] = fit_vertex(mesh, rings, first + l, method, extra_rings, s);
    else if (g.points[l] > 0)
      out[l].curvature = pc[l];
  }
}

}  // namespace

void fit_vertices(const Mesh& mesh, const VertexRings& rings, int32_t first, int count, CurvatureMethod method,
                  int extra_rings, VertexFitScratch& s, VertexFitResult (&out)[8]) {
  // Lanes 0-3 (vertices first to first + 3) are group 0, lanes 4-7 group 1;
  // with four vertices or fewer, group 0 alone.
  const int groups = count > 4 ? 2 : 1;
  const FitModel model = plan_of(method).model;
  const int wanted = points_wanted(model);
  LaneGroupState g[2];
  int widest = 0;
  for (int k = 0; k < groups; ++k) {
    const int in_group = std::min(4, count - 4 * k);
    widest = std::max(widest, start_group(mesh, rings, first + 4 * k, in_group, method, extra_rings, wanted, s,
                                          s.lane_rings[k], g[k], out + 4 * k));
  }
  HeightFit fit[2][4];
  if (widest > 0) {
    LaneGroup lanes[2];
    for (int k = 0; k < groups; ++k) {
      group_coordinates(mesh, wanted, widest, s.lane_rings[k], g[k],
                        s.lanes[k]);
      lanes[k] = {s.lanes[k].u.data(), s.lanes[k].v.data(), s.lanes[k].d.data(),
                  {g[k].points[0], g[k].points[1], g[k].points[2], g[k].points[3]}};
    }
    if (groups == 2)
      fit_height_lanes(model, lanes, fit);
    else
      fit_height_lanes(model, lanes[0].u, lanes[0].v, lanes[0].d, lanes[0].count, fit[0]);
  }
  for (int k = 0; k < groups; ++k)
    finish_group(mesh, rings, first + 4 * k, std::min(4, count - 4 * k), method, extra_rings, s, g[k], fit[k],
                 out + 4 * k);
}

}  // namespace isoform
