// The lane kernels of the batch evaluation (batch_eval.h): fast_eval.h's
// edge value, radial conic (conic.h's make_conic) and radial point, written
// over lanes_jet.h's four-sample jets. Each function mirrors its scalar
// original step by step; where the original branches on a value, rare
// branches set `bad` for the lane (the caller evaluates it by the scalar
// path) and common ones become selects.
#pragma once

#include "conic.h"
#include "edge_poly.h"
#include "lanes_jet.h"

namespace isoform::patch::lanes {

template <bool S>
using V1 = V3<J1<S>>;
template <bool S>
using V2 = V3<J2<S>>;

template <bool S>
ISOFORM_JET_INLINE J1<S> operator*(const J1<S>& a, L c) {
  return c * a;
}
ISOFORM_JET_INLINE double comp(const V3d& a, int i) { return i == 0 ? a.x : (i == 1 ? a.y : a.z); }
template <class T>
ISOFORM_JET_INLINE const T& comp(const V3<T>& a, int i) {
  return i == 0 ? a.x : (i == 1 ? a.y : a.z);
}
template <bool S>
ISOFORM_JET_INLINE V1<S> plus(const V3d& a, const V1<S>& b) {
  return {b.x + a.x, b.y + a.y, b.z + a.z};
}
template <bool S>
ISOFORM_JET_INLINE V1<S> cross_c(const V3d& a, const V1<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <bool S>
ISOFORM_JET_INLINE L norm2_value(const V1<S>& a) {
  return a.x.v * a.x.v + a.y.v * a.y.v + a.z.v * a.z.v;
}
template <bool S>
ISOFORM_JET_INLINE V1<S> unit_l(const V1<S>& a) {
  return reciprocal(sqrt(dot(a, a))) * a;
}

// fast_eval.h's edge_value: point and normal n_S of the edge at tc (per
// lane), as jets in the block's t (d tc / dt = sigma).
template <bool S>
ISOFORM_JET_INLINE void edge_value(const EdgePoly& e, L tc, double sigma, V1<S>& point, V1<S>& normal, M& bad) {
  const L t = tc, t2 = t * t;
  const L D0 = e.den[0] + t * e.den[1] + t2 * e.den[2] + t2 * t * e.den[3];
  const L D1 = e.den[1] + 2.0 * t * e.den[2] + 3.0 * t2 * e.den[3];
  const L D2 = 2.0 * e.den[2] + 6.0 * t * e.den[3];
  const double D3 = 6.0 * e.den[3];
  const L inv = 1.0 / D0;
  J1<S> P[3], T[3];
  for (int a = 0; a < 3; ++a) {
    const double n0 = comp(e.num[0], a), n1 = comp(e.num[1], a), n2 = comp(e.num[2], a), n3 = comp(e.num[3], a);
    const L N0 = n0 + t * n1 + t2 * n2 + (t2 * t) * n3;
    const L N1 = n1 + (2.0 * t) * n2 + (3.0 * t2) * n3;
    const L N2 = 2.0 * n2 + (6.0 * t) * n3;
    const L C0 = inv * N0, C1 = inv * (N1 - D1 * C0), C2 = inv * (N2 - (2.0 * D1) * C1 - D2 * C0);
    P[a] = J1<S>(C0, sigma * C1, C2);
    L C3{};
    if constexpr (S) C3 = inv * (6.0 * n3 - (3.0 * D1) * C2 - (3.0 * D2) * C1 - D3 * C0);
    T[a] = J1<S>(C1, sigma * C2, C3);
  }
  point = V1<S>(P[0], P[1], P[2]);
  const V1<S> tangent(T[0], T[1], T[2]);
  // NOTE: the scalar path takes a fixed tangent for a point edge: rare.
  bad |= ~(norm2_value(tangent) > 0.0);
  const V1<S> nc = cross_c(e.p, unit_l(tangent));
  const L theta = e.theta0 + tc * e.dtheta;
  L st, ct;
  lane_sincos(theta, st, ct);
  const double dth = sigma * e.dtheta;
  const J1<S> cos_t(ct, -st * dth, -ct * (dth * dth)), sin_t(st, ct * dth, -st * (dth * dth));
  normal = V1<S>(cos_t * nc.x + sin_t * e.p.x, cos_t * nc.y + sin_t * e.p.y, cos_t * nc.z + sin_t * e.p.z);
}

// conic.h's half_angle, both branches as one with a swap.
template <bool S>
ISOFORM_JET_INLINE void half_angle(const J1<S>& c, const J1<S>& s, J1<S>& ch, J1<S>& sh) {
  const M positive = c.v >= 0.0;
  const L sign = select(positive, splat(1.0), splat(-1.0));
  const J1<S> x = sqrt(0.5 + 0.5 * (sign * c));
  const J1<S> y = s * reciprocal(2.0 * x);
  ch = select(positive, x, y);
  sh = select(positive, y, x);
}

// A radial conic: b0 is the vertex (a constant), b3 the edge point.
template <bool S>
struct Radial {
  V1<S> b1, b2, b3;
  J1<S> w;
};

// conic.h's make_conic from the vertex (b0, n0) to the edge point (b3, n3);
// inv_tension null for automatic weights (the constant 0). Written into c
// (a copy of the result would cost more than some of its steps).
template <bool S>
ISOFORM_JET_INLINE void radial_conic(const V3d& b0, const V3d& n0, const V1<S>& b3, const V1<S>& n3,
                                     const J1<S>* inv_tension, M& bad, Radial<S>& c) {
  c.b3 = b3;
  const V1<S> d = plus(-b0, b3);
  const J1<S> len = sqrt(dot(d, d));
  bad |= ~(len.v > 0.0);
  const V1<S> dh = reciprocal(len) * d;
  // NOTE: the scalar thresholds (1e-9, 1e-12) doubled: lanes near them go
  // the scalar way, so both paths take the same branch.
  const V1<S> m = plus(n0, n3);
  bad |= norm2_value(m) < 4e-18;
  const V1<S> pc = cross(dh, m);
  bad |= norm2_value(pc) < 4e-24;
  const V1<S> p = unit_l(pc);
  const V1<S> u0 = cross_c(n0, p), u3 = cross(n3, p);
  bad |= (norm2_value(u0) < 4e-24) | (norm2_value(u3) < 4e-24);
  const V1<S> t0 = unit_l(u0), t3 = unit_l(u3);
  const V1<S> e = cross(p, dh);
  const J1<S> sin_alpha = abs(dot(t0, e)), sin_beta = abs(dot(t3, e));
  J1<S> ca, sa, cb, sb;
  half_angle(dot(t0, dh), sin_alpha, ca, sa);
  half_angle(dot(t3, dh), sin_beta, cb, sb);
  J1<S> a = ca * cb - sa * sb;
  a = select(a.v < 0.0, zero1<S>(), a);
  J1<S> omega = a, scaled_len = len;
  if (inv_tension) {
    const J1<S> x = a * *inv_tension;
    const J1<S> q = reciprocal(sqrt(1.0 + x * x));
    omega = q * a;
    scaled_len = q * len;
  }
  const J1<S> cos_half_gamma = sa * cb + ca * sb;
  const J1<S> inv_den = reciprocal(cos_half_gamma + kFlatAngle);
  const J1<S> ratio_0 = (sin_beta + kFlatAngle) * inv_den, ratio_3 = (sin_alpha + kFlatAngle) * inv_den;
  const J1<S> one_2w = 1.0 + 2.0 * omega;
  const J1<S> scale = scaled_len / one_2w;
  c.b1 = plus(b0, (scale * ratio_0) * t0);
  c.b2 = b3 - (scale * ratio_3) * t3;
  c.w = one_2w * (1.0 / 3.0);
}

// fast_eval.h's radial_point: the rational cubic at r with its partials in
// (t, r), composed with the jets t(u, v) and r(u, v).
template <bool S>
ISOFORM_JET_INLINE V2<S> radial_point(const V3d& b0, const Radial<S>& c, const J2<S>& tl, const J2<S>& rj) {
  const L r = rj.v, s = 1.0 - r;
  const L B[4] = {s * s * s, 3.0 * s * s * r, 3.0 * s * r * r, r * r * r};
  const L dB[4] = {-3.0 * s * s, 3.0 * (s * s - 2.0 * s * r), 3.0 * (2.0 * s * r - r * r), 3.0 * r * r};
  const L ddB[4] = {6.0 * s, 6.0 * r - 12.0 * s, 6.0 * s - 12.0 * r, 6.0 * r};
  const J1<S>& w = c.w;
  const L D = B[0] + B[3] + (B[1] + B[2]) * w.v, Dt = (B[1] + B[2]) * w.d;
  const L Dr = dB[0] + dB[3] + (dB[1] + dB[2]) * w.v;
  const L invD = 1.0 / D;
  J2<S> g[3];
  for (int a = 0; a < 3; ++a) {
    const double b0v = comp(b0, a);
    const J1<S>&b1 = comp(c.b1, a), &b2 = comp(c.b2, a), &b3 = comp(c.b3, a);
    const J1<S> P1 = w * b1, P2 = w * b2;
    const L N = B[0] * b0v + B[1] * P1.v + B[2] * P2.v + B[3] * b3.v;
    const L Nt = B[1] * P1.d + B[2] * P2.d + B[3] * b3.d;
    const L Nr = dB[0] * b0v + dB[1] * P1.v + dB[2] * P2.v + dB[3] * b3.v;
    const L F = N * invD, Ft = (Nt - Dt * F) * invD, Fr = (Nr - Dr * F) * invD;
    g[a].v = F;
    for (int i = 0; i < 2; ++i) g[a].d[i] = Ft * tl.d[i] + Fr * rj.d[i];
    if constexpr (S) {
      const L Dtt = (B[1] + B[2]) * w.h, Dtr = (dB[1] + dB[2]) * w.d;
      const L Drr = ddB[0] + ddB[3] + (ddB[1] + ddB[2]) * w.v;
      const L Ntt = B[1] * P1.h + B[2] * P2.h + B[3] * b3.h;
      const L Ntr = dB[1] * P1.d + dB[2] * P2.d + dB[3] * b3.d;
      const L Nrr = ddB[0] * b0v + ddB[1] * P1.v + ddB[2] * P2.v + ddB[3] * b3.v;
      const L Ftt = (Ntt - 2.0 * Dt * Ft - Dtt * F) * invD;
      const L Frr = (Nrr - 2.0 * Dr * Fr - Drr * F) * invD;
      const L Ftr = (Ntr - Dt * Fr - Dr * Ft - Dtr * F) * invD;
      const int ia[3] = {0, 0, 1}, ib[3] = {0, 1, 1};
      for (int k = 0; k < 3; ++k) {
        const int i = ia[k], j = ib[k];
        g[a].h[k] = Ftt * tl.d[i] * tl.d[j] + Ftr * (tl.d[i] * rj.d[j] + tl.d[j] * rj.d[i]) +
                    Frr * rj.d[i] * rj.d[j] + Ft * tl.h[k] + Fr * rj.h[k];
      }
    }
  }
  return V2<S>(g[0], g[1], g[2]);
}

}  // namespace isoform::patch::lanes
