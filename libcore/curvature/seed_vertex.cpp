// The seed's fit at one vertex without the general path's copies; each step
// is fit_vertex's own arithmetic in fit_vertex's order, so the bits match.
#include "seed_vertex.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "principal_lanes.h"
#include "ring_coordinates.h"
#include "small_ldlt.h"
#include "small_ldlt_lanes.h"
#include "vector_level.h"

namespace isoform {
namespace {

using Eigen::Vector3d;

// Rings longer than this go the general way (no fixed-size buffer).
constexpr size_t kMaxValence = 32;

// Adds one point (x, y scaled, height h) to the seed fit's five moments
// u^4, u^3 v, u^2 v^2, u v^3, v^4 and its sums d u^2, d u v, d v^2, as
// fit_height adds it; T is double for one point set, Lanes4 for four.
template <class T>
ISOFORM_LANES_INLINE void add_seed_point(T x, T y, T h, T (&moment)[5], T (&rhs)[3]) {
  const T x2 = x * x, y2 = y * y, x3 = x2 * x, y3 = y2 * y;
  moment[0] += x3 * x;
  moment[1] += x3 * y;
  moment[2] += x2 * y2;
  moment[3] += x * y3;
  moment[4] += y3 * y;
  rhs[0] += h * x2;
  rhs[1] += h * (x * y);
  rhs[2] += h * y2;
}

// fit_height(FitModel::SeedQuadratic, ...) for count >= 3 points, with
// fit_height's arithmetic in its order: the scale, the five moments u^4 ..
// v^4 and three sums d u^2, d u v, d v^2, the 3 x 3 LDLT, the
// conditioning test.
bool seed_fit(const double* u, const double* v, const double* d, int count, HeightFit& out) {
  double r2 = 0.0;
  for (int j = 0; j < count; ++j) r2 = std::max(r2, u[j] * u[j] + v[j] * v[j]);
  const double scale = std::sqrt(r2);
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  const double inv = 1.0 / scale;
  // One sum per moment, over the points in their order, as fit_height
  // sums them.
  double moment[5] = {0, 0, 0, 0, 0}, rhs[3] = {0, 0, 0};
  for (int j = 0; j < count; ++j) add_seed_point(u[j] * inv, v[j] * inv, d[j], moment, rhs);
  // Terms u^2, u v, v^2: entry (r, c) is the moment of v-power r + c.
  static constexpr int at[3][3] = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}};
  SmallLdlt<3> ldlt;
  if (!ldlt.factor(moment, at)) return false;
  double hi = 0.0, lo = ldlt.d(0);
  for (int i = 0; i < 3; ++i) {
    hi = std::max(hi, std::abs(ldlt.d(i)));
    lo = std::min(lo, ldlt.d(i));
  }
  const double rcond = hi > 0.0 ? lo / hi : 0.0;
  if (!(lo > 0.0 && rcond >= 1e-10)) return false;
  double c[3];
  ldlt.solve(rhs, c);
  for (double x : c)
    if (!std::isfinite(x)) return false;
  const double inv2 = inv * inv;
  out.fuu = 2.0 * c[0] * inv2;
  out.fuv = c[1] * inv2;
  out.fvv = 2.0 * c[2] * inv2;
  out.rcond = rcond;
  out.ok = true;
  return true;
}

}  // namespace

VertexFitResult fit_seed_vertex(const Mesh& mesh, const VertexRings& rings, int32_t v, VertexFitScratch& s) {
  VertexFitResult r;
  const size_t valence = rings.valence(v);
  if (valence == 0) {
    r.flags = kCurvatureIsolated;
    return r;
  }
  if (valence > kMaxValence || mesh.normals.size() != mesh.points.size())
    return fit_vertex(mesh, rings, v, CurvatureMethod::Seed, 0, s);
  // frame_normal's test of the given normal.
  const float* q = &mesh.normals[3 * size_t(v)];
  Vector3d n(q[0], q[1], q[2]);
  const double len = n.norm();
  if (!(std::isfinite(len) && len > 0.5)) return fit_vertex(mesh, rings, v, CurvatureMethod::Seed, 0, s);
  n /= len;
  const Vector3d b1 = n.unitOrthogonal();
  const Vector3d b2 = n.cross(b1);
  double u[kMaxValence + 1], w[kMaxValence + 1], d[kMaxValence + 1];
  const int32_t *first = rings.ring_begin(v), *last = rings.ring_end(v);
  const int count = mesh.precise_points.size() == mesh.points.size()
                        ? ring_coordinates(mesh.precise_points.data(), v, first, last, b1, b2, n, u, w, d)
                        : ring_coordinates(mesh.points.data(), v, first, last, b1, b2, n, u, w, d);
  if (count < fit_terms(FitModel::SeedQuadratic)) return fit_vertex(mesh, rings, v, CurvatureMethod::Seed, 0, s);
  HeightFit fit;  // fu = fv = 0: principal_curvatures_inline folds them away
  if (!seed_fit(u, w, d, count, fit)) return fit_vertex(mesh, rings, v, CurvatureMethod::Seed, 0, s);
  if (rings.nonmanifold(v)) r.flags |= kCurvatureNonmanifold;
  r.curvature = principal_curvatures_inline(fit, b1, b2, n);
  return r;
}

namespace {

// seed_fit for four point sets side by side (point j of lane l at
// u[j][l]; lanes with fewer points padded with zeros, which add exactly 0
// to every sum and leave the largest radius as it is). ok[l] false where
// seed_fit would return false for lane l.
ISOFORM_LANES_INLINE void seed_fit_lanes(const Lanes4* u, const Lanes4* v, const Lanes4* d, int most,
                                          HeightFitLanes& out, bool (&ok)[4]) {
  Lanes4 r2 = splat4(0.0);
  for (int j = 0; j < most; ++j) r2 = max4(r2, u[j] * u[j] + v[j] * v[j]);
  const Lanes4 scale = sqrt4(r2);
  const Mask4 scaled = (scale > splat4(0.0)) & finite4(scale);
  const Lanes4 inv = splat4(1.0) / scale;
  Lanes4 moment[5] = {}, rhs[3] = {};
  for (int j = 0; j < most; ++j) add_seed_point(u[j] * inv, v[j] * inv, d[j], moment, rhs);
  static constexpr int at[3][3] = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}};
  SmallLdltLanes<3> ldlt;
  bool factored[4];
  ldlt.factor(moment, at, factored);
  Lanes4 hi = splat4(0.0), lo = ldlt.diagonal(0);
  for (int i = 0; i < 3; ++i) {
    hi = max4(hi, abs4(ldlt.diagonal(i)));
    lo = min4(lo, ldlt.diagonal(i));
  }
  const Lanes4 rcond = select4(hi > splat4(0.0), lo / hi, splat4(0.0));
  const Mask4 conditioned = (lo > splat4(0.0)) & (rcond >= splat4(1e-10));
  Lanes4 c[3];
  ldlt.solve(rhs, c);
  const Mask4 finite = finite4(c[0]) & finite4(c[1]) & finite4(c[2]);
  const Mask4 good = scaled & conditioned & finite;
  for (int l = 0; l < 4; ++l) ok[l] = factored[l] && good[l] != 0;
  const Lanes4 inv2 = inv * inv;
  out.fu = out.fv = splat4(0.0);
  out.fuu = splat4(2.0) * c[0] * inv2;
  out.fuv = c[1] * inv2;
  out.fvv = splat4(2.0) * c[2] * inv2;
}

ISOFORM_LANES_INLINE bool seed_vertices_body(const Mesh& mesh, const VertexRings& rings, int32_t first, int count,
                                             VertexFitScratch& s, VertexFitResult (&out)[4], SeedLanes* lanes) {
  // Lanes that the short path cannot settle at once (no usable normal,
  // fewer than three points, a large valence, a neighbour on the vertex)
  // go through fit_seed_vertex alone.
  bool alone[4] = {true, true, true, true};
  int32_t vertex[4];
  const int32_t* ring[4];
  int valence[4];
  const bool normals = mesh.normals.size() == mesh.points.size();
  static const float kUp[3] = {0.0f, 0.0f, 1.0f};
  const float* q[4];
  for (int l = 0; l < 4; ++l) {
    vertex[l] = first + std::min(l, count - 1);
    ring[l] = rings.ring_begin(vertex[l]);
    valence[l] = 0;
    q[l] = kUp;
    if (l >= count || !normals) continue;
    const size_t m = rings.valence(vertex[l]);
    if (m < size_t(fit_terms(FitModel::SeedQuadratic)) || m > kMaxValence) continue;
    q[l] = &mesh.normals[3 * size_t(vertex[l])];
    valence[l] = int(m);
    alone[l] = false;
  }
  Vec3Lanes n = {Lanes4{q[0][0], q[1][0], q[2][0], q[3][0]}, Lanes4{q[0][1], q[1][1], q[2][1], q[3][1]},
                 Lanes4{q[0][2], q[1][2], q[2][2], q[3][2]}};
  // frame_normal's test and normalisation of the given normals.
  const Lanes4 len = sqrt4((n.x * n.x + n.y * n.y) + n.z * n.z);
  const Mask4 usable = finite4(len) & (len > splat4(0.5));
  for (int l = 0; l < 4; ++l)
    if (!usable[l]) alone[l] = true;
  n = {n.x / len, n.y / len, n.z / len};
  Vec3Lanes b1, b2;
  frame_lanes(n, b1, b2);
  Lanes4 u[kMaxValence], v[kMaxValence], d[kMaxValence];
  bool coincide[4];
  const int most = mesh.precise_points.size() == mesh.points.size()
                       ? ring_coordinates_lanes(mesh.precise_points.data(), vertex, ring, valence, b1, b2, n,
                                                (double*)u, (double*)v, (double*)d, coincide)
                       : ring_coordinates_lanes(mesh.points.data(), vertex, ring, valence, b1, b2, n, (double*)u,
                                                (double*)v, (double*)d, coincide);
  HeightFitLanes fit;
  bool ok[4];
  seed_fit_lanes(u, v, d, most, fit, ok);
  const PrincipalLanes p = principal_curvatures_lanes(fit, b1, b2, n);
  if (lanes && count == 4) {
    bool settled = true;
    for (int l = 0; l < 4; ++l) settled &= !alone[l] && !coincide[l] && ok[l];
    if (settled) {
      auto put = [](double* to, Lanes4 x) { __builtin_memcpy(to, &x, sizeof(x)); };
      put(lanes->k1, p.k1);
      put(lanes->k2, p.k2);
      put(lanes->d1[0], p.d1.x);
      put(lanes->d1[1], p.d1.y);
      put(lanes->d1[2], p.d1.z);
      put(lanes->d2[0], p.d2.x);
      put(lanes->d2[1], p.d2.y);
      put(lanes->d2[2], p.d2.z);
      for (int l = 0; l < 4; ++l) lanes->flags[l] = rings.nonmanifold(vertex[l]) ? kCurvatureNonmanifold : 0;
      return true;
    }
  }
  for (int l = 0; l < count; ++l) {
    if (alone[l] || coincide[l] || !ok[l]) {
      out[l] = fit_seed_vertex(mesh, rings, vertex[l], s);
      continue;
    }
    out[l].flags = rings.nonmanifold(vertex[l]) ? kCurvatureNonmanifold : 0;
    out[l].curvature = principal_of_lane(p, l);
  }
  return false;
}

// The four-lane path built for AVX too, chosen at run time (vector_level.h):
// the same operations, so the same bits; the baseline build splits each
// vector operation into two or four.
bool seed_vertices_plain(const Mesh& mesh, const VertexRings& rings, int32_t first, int count, VertexFitScratch& s,
                         VertexFitResult (&out)[4], SeedLanes* lanes) {
  return seed_vertices_body(mesh, rings, first, count, s, out, lanes);
}

#ifdef ISOFORM_AVX_CLONE
ISOFORM_AVX_TARGET bool seed_vertices_avx(const Mesh& mesh, const VertexRings& rings, int32_t first, int count,
                                          VertexFitScratch& s, VertexFitResult (&out)[4], SeedLanes* lanes) {
  return seed_vertices_body(mesh, rings, first, count, s, out, lanes);
}
ISOFORM_AVX512_TARGET bool seed_vertices_avx512(const Mesh& mesh, const VertexRings& rings, int32_t first, int count,
                                                VertexFitScratch& s, VertexFitResult (&out)[4], SeedLanes* lanes) {
  return seed_vertices_body(mesh, rings, first, count, s, out, lanes);
}
#endif

}  // namespace

bool fit_seed_vertices(const Mesh& mesh, const VertexRings& rings, int32_t first, int count, VertexFitScratch& s,
                       VertexFitResult (&out)[4], SeedLanes* lanes) {
#ifdef ISOFORM_AVX_CLONE
  if (vector_level() == 2) return seed_vertices_avx512(mesh, rings, first, count, s, out, lanes);
  if (vector_level() > 0) return seed_vertices_avx(mesh, rings, first, count, s, out, lanes);
#endif
  return seed_vertices_plain(mesh, rings, first, count, s, out, lanes);
}

}  // namespace isoform
