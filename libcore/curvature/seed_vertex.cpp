// The seed's fit at one vertex without the general path's copies; each step
// is fit_vertex's own arithmetic in fit_vertex's order, so the bits match.
#include "seed_vertex.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "ring_coordinates.h"
#include "small_ldlt.h"

namespace isoform {
namespace {

using Eigen::Vector3d;

// Rings longer than this go the general way (no fixed-size buffer).
constexpr size_t kMaxValence = 32;

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
  for (int j = 0; j < count; ++j) {
    const double x = u[j] * inv, y = v[j] * inv, h = d[j];
    const double x2 = x * x, y2 = y * y, x3 = x2 * x, y3 = y2 * y;
    moment[0] += x3 * x;
    moment[1] += x3 * y;
    moment[2] += x2 * y2;
    moment[3] += x * y3;
    moment[4] += y3 * y;
    rhs[0] += h * x2;
    rhs[1] += h * (x * y);
    rhs[2] += h * y2;
  }
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
  const double s2 = scale * scale;
  out.fuu = 2.0 * c[0] / s2;
  out.fuv = c[1] / s2;
  out.fvv = 2.0 * c[2] / s2;
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

}  // namespace isoform
