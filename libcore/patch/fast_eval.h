// The fast evaluation of the side-vertex patch: the same surface as
// patch_eval.h (the reference), organised around what each part depends on.
// Building block s_i is F(t, r): the radial conic, built from vertex i to the
// point of edge e_i at t = u_k / (u_j + u_k), evaluated at r = u_j + u_k.
// Everything about the radial conic (the edge's point and normal, the plane,
// tangents, angles, weight, Bezier points) depends on t alone, so it is built
// with one-variable jets (jet1.h); the rational cubic in r is then evaluated
// with its partial derivatives in t and r by hand, and the chain rule through
// t(u, v) and r(u, v) gives the derivatives in (u, v). Exact derivatives, as
// in the reference (tests/patch: FastPath.*).
#pragma once

#include "side_vertex_surface.h"

namespace isoform::patch {
namespace fast {

// Point and normal n_S of the edge at tc, as jets in the block's t, where
// tc = t (sigma = 1) or 1 - t (sigma = -1).
template <bool S>
ISOFORM_JET_INLINE EdgeValue<Jet1<S>> edge_value(const EdgePoly& e, double tc, double sigma) {
  // Numerator and denominator with their first three derivatives in tc.
  const double t = tc, t2 = t * t;
  V3d N[4];
  N[0] = e.num[0] + t * e.num[1] + t2 * e.num[2] + (t2 * t) * e.num[3];
  N[1] = e.num[1] + (2.0 * t) * e.num[2] + (3.0 * t2) * e.num[3];
  N[2] = 2.0 * e.num[2] + (6.0 * t) * e.num[3];
  N[3] = 6.0 * e.num[3];
  const double D0 = e.den[0] + t * e.den[1] + t2 * e.den[2] + t2 * t * e.den[3];
  const double D1 = e.den[1] + 2.0 * t * e.den[2] + 3.0 * t2 * e.den[3];
  const double D2 = 2.0 * e.den[2] + 6.0 * t * e.den[3], D3 = 6.0 * e.den[3];
  const double inv = 1.0 / D0;
  const V3d C0 = inv * N[0];
  const V3d C1 = inv * (N[1] - D1 * C0);
  const V3d C2 = inv * (N[2] - (2.0 * D1) * C1 - D2 * C0);
  EdgeValue<Jet1<S>> r;
  using J = Jet1<S>;
  const double s2 = sigma;  // d tc / dt; its square is 1
  r.point = V3<J>(J(C0.x, s2 * C1.x, C2.x), J(C0.y, s2 * C1.y, C2.y), J(C0.z, s2 * C1.z, C2.z));
  V3<J> tangent;
  if constexpr (S) {
    const V3d C3 = inv * (N[3] - (3.0 * D1) * C2 - (3.0 * D2) * C1 - D3 * C0);
    tangent = V3<J>(J(C1.x, s2 * C2.x, C3.x), J(C1.y, s2 * C2.y, C3.y), J(C1.z, s2 * C2.z, C3.z));
  } else {
    tangent = V3<J>(J(C1.x, s2 * C2.x, 0.0), J(C1.y, s2 * C2.y, 0.0), J(C1.z, s2 * C2.z, 0.0));
  }
  // NOTE: as edge_eval: a degenerate (point) edge has no tangent.
  if (!(norm_value(tangent) > 0.0)) tangent = V3<J>::from(e.t0);
  const V3<J> T_unit = unit(tangent);
  const V3<J> nc = cross(V3<J>::from(e.p), T_unit);
  const double theta = e.theta0 + tc * e.dtheta, st = std::sin(theta), ct = std::cos(theta);
  const double dth = sigma * e.dtheta;
  const J cos_t = J(ct, -st * dth, -ct * dth * dth), sin_t = J(st, ct * dth, -st * dth * dth);
  r.normal = cos_t * nc + V3<J>(sin_t * e.p.x, sin_t * e.p.y, sin_t * e.p.z);
  return r;
}

// The rational cubic of a radial conic (control points jets in t) at r, with
// the partial derivatives of F(t, r), composed with the jets t(u, v) and
// r(u, v).
template <bool S>
ISOFORM_JET_INLINE V3<Jet<S>> radial_point(const Conic<Jet1<S>>& c, const Jet<S>& tl, const Jet<S>& rj) {
  const double r = rj.v, s = 1.0 - r;
  const double B[4] = {s * s * s, 3.0 * s * s * r, 3.0 * s * r * r, r * r * r};
  const double dB[4] = {-3.0 * s * s, 3.0 * (s * s - 2.0 * s * r), 3.0 * (2.0 * s * r - r * r), 3.0 * r * r};
  const double ddB[4] = {6.0 * s, 6.0 * r - 12.0 * s, 6.0 * s - 12.0 * r, 6.0 * r};
  const Jet1<S>& w = c.w;
  // Denominator and its partials (b0, b3 have weight 1).
  const double D = B[0] + B[3] + (B[1] + B[2]) * w.v, Dt = (B[1] + B[2]) * w.d;
  const double Dr = dB[0] + dB[3] + (dB[1] + dB[2]) * w.v;
  const double invD = 1.0 / D;
  V3<Jet<S>> out;
  Jet<S>* o[3] = {&out.x, &out.y, &out.z};
  for (int a = 0; a < 3; ++a) {
    const Jet1<S>* b[4];
    for (int k = 0; k < 4; ++k) b[k] = a == 0 ? &c.b[k].x : (a == 1 ? &c.b[k].y : &c.b[k].z);
    // Homogeneous points w_k b_k as jets in t.
    const Jet1<S> P1 = w * *b[1], P2 = w * *b[2];
    const double N = B[0] * b[0]->v + B[1] * P1.v + B[2] * P2.v + B[3] * b[3]->v;
    const double Nt = B[0] * b[0]->d + B[1] * P1.d + B[2] * P2.d + B[3] * b[3]->d;
    const double Nr = dB[0] * b[0]->v + dB[1] * P1.v + dB[2] * P2.v + dB[3] * b[3]->v;
    const double F = N * invD, Ft = (Nt - Dt * F) * invD, Fr = (Nr - Dr * F) * invD;
    Jet<S>& g = *o[a];
    g.v = F;
    for (int i = 0; i < 2; ++i) g.d[i] = Ft * tl.d[i] + Fr * rj.d[i];
    if constexpr (S) {
      const double Dtt = (B[1] + B[2]) * w.h, Dtr = (dB[1] + dB[2]) * w.d;
      const double Drr = ddB[0] + ddB[3] + (ddB[1] + ddB[2]) * w.v;
      const double Ntt = B[0] * b[0]->h + B[1] * P1.h + B[2] * P2.h + B[3] * b[3]->h;
      const double Ntr = dB[0] * b[0]->d + dB[1] * P1.d + dB[2] * P2.d + dB[3] * b[3]->d;
      const double Nrr = ddB[0] * b[0]->v + ddB[1] * P1.v + ddB[2] * P2.v + ddB[3] * b[3]->v;
      const double Ftt = (Ntt - 2.0 * Dt * Ft - Dtt * F) * invD;
      const double Frr = (Nrr - 2.0 * Dr * Fr - Drr * F) * invD;
      const double Ftr = (Ntr - Dt * Fr - Dr * Ft - Dtr * F) * invD;
      const int ia[3] = {0, 0, 1}, ib[3] = {0, 1, 1};
      for (int k = 0; k < 3; ++k) {
        const int i = ia[k], j = ib[k];
        g.h[k] = Ftt * tl.d[i] * tl.d[j] + Ftr * (tl.d[i] * rj.d[j] + tl.d[j] * rj.d[i]) + Frr * rj.d[i] * rj.d[j] +
                 Ft * tl.h[k] + Fr * rj.h[k];
      }
    }
  }
  return out;
}

// Building block s_i as a jet in (u, v); same construction as
// patch_eval.h's building_block.
template <bool S>
ISOFORM_JET_INLINE V3<Jet<S>> building_block(const SideVertexSurface& s, size_t tri, int i, const Jet<S>* bary) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const Jet<S> rest = bary[j] + bary[k];
  const Jet<S> t_local = bary[k] / rest;  // 0 at vertex j, 1 at vertex k
  const TriangleEdge te = s.triangle_edge(tri, i);
  const double t = t_local.v;
  using J = Jet1<S>;
  const EdgeValue<J> q =
      edge_value<S>(s.edge_poly(size_t(te.edge)), te.reversed ? 1.0 - t : t, te.reversed ? -1.0 : 1.0);
  const double inv_ij = s.edge_inv_tension(size_t(s.triangle_edge(tri, k).edge));
  const double inv_ik = s.edge_inv_tension(size_t(s.triangle_edge(tri, j).edge));
  const J inv(inv_ij + t * (inv_ik - inv_ij), inv_ik - inv_ij, 0.0);
  const int32_t vi = s.triangle_vertex(tri, i);
  const Conic<J> radial =
      make_conic(V3<J>::from(s.vertex(size_t(vi))), V3<J>::from(s.vertex_normal(size_t(vi))), q.point, q.normal, inv);
  return radial_point<S>(radial, t_local, rest);
}

// The blend (6.1), as patch_eval.h's patch_point.
template <bool S>
bool patch_point(const SideVertexSurface& s, size_t tri, double u, double v, V3<Jet<S>>& out) {
  const Jet<S> uj = Jet<S>::variable(u, 0), vj = Jet<S>::variable(v, 1);
  const Jet<S> bary[3] = {1.0 - uj - vj, uj, vj};
  Jet<S> weight[3];
  Jet<S> sum(0.0);
  for (int i = 0; i < 3; ++i) {
    const Jet<S> w = bary[(i + 1) % 3] * bary[(i + 2) % 3];
    weight[i] = s.options().blend == Blend::Squared ? w * w : w;
    sum = sum + weight[i];
  }
  if (!(sum.v >= 1e-300)) return false;
  const Jet<S> inv = 1.0 / sum;
  V3<Jet<S>> p(Jet<S>(0.0), Jet<S>(0.0), Jet<S>(0.0));
  for (int i = 0; i < 3; ++i) p = p + (weight[i] * inv) * building_block<S>(s, tri, i, bary);
  out = p;
  return true;
}

}  // namespace fast
}  // namespace isoform::patch
