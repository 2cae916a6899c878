// Jets (jet.h, jet1.h) over four samples at once: every part of a jet is a
// vector of four doubles (GCC vector extensions), one sample per lane, so
// the batch evaluation (batch_eval.cpp) runs the construction of four radial
// conics or four patch points with the same instructions. Branches on values
// become per-lane selects; the caller sends lanes whose data take a rare
// branch to the scalar path.
#pragma once

#include <cmath>

#include "vec3.h"

namespace isoform::patch::lanes {

typedef double L __attribute__((vector_size(32)));
typedef long long M __attribute__((vector_size(32)));  // lane masks: 0 or -1

ISOFORM_JET_INLINE L splat(double x) { return L{x, x, x, x}; }
ISOFORM_JET_INLINE L select(M m, L a, L b) { return m ? a : b; }
ISOFORM_JET_INLINE bool any(M m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }
// NOTE: the file is built with -fno-math-errno, so these are sqrt instructions.
ISOFORM_JET_INLINE L lane_sqrt(L x) {
  return L{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
}

// Rows a, b, c, d of a 4 x 4 matrix become its columns.
ISOFORM_JET_INLINE void transpose4(L& a, L& b, L& c, L& d) {
  const L t0 = __builtin_shufflevector(a, b, 0, 4, 2, 6), t1 = __builtin_shufflevector(a, b, 1, 5, 3, 7);
  const L t2 = __builtin_shufflevector(c, d, 0, 4, 2, 6), t3 = __builtin_shufflevector(c, d, 1, 5, 3, 7);
  a = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
  b = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
  c = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
  d = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

// sin and cos per lane, to about an ulp of libm's: x = k pi/2 + r with
// |r| <= pi/4 (pi/2 in two parts: k pi/2 is exact for the small k of
// angles), Taylor series to r^17 / r^16 (the next terms are below 1e-17 on
// |r| <= pi/4), and the quadrant k mod 4 picks and signs the two.
ISOFORM_JET_INLINE void lane_sincos(L x, L& sin_x, L& cos_x) {
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52: adds to round
  constexpr double kHalfPiHi = double(float(M_PI_2)), kHalfPiLo = M_PI_2 - kHalfPiHi;
  const L k = (x * M_2_PI + kRound) - kRound;
  const L r = (x - k * kHalfPiHi) - k * kHalfPiLo;
  const L r2 = r * r;
  // 1/n! for the odd (sine) and even (cosine) terms.
  const double s3 = -1.0 / 6, s5 = 1.0 / 120, s7 = -1.0 / 5040, s9 = 1.0 / 362880, s11 = -1.0 / 39916800,
               s13 = 1.0 / 6227020800.0, s15 = -1.0 / 1307674368000.0, s17 = 1.0 / 355687428096000.0;
  const double c2 = -0.5, c4 = 1.0 / 24, c6 = -1.0 / 720, c8 = 1.0 / 40320, c10 = -1.0 / 3628800,
               c12 = 1.0 / 479001600.0, c14 = -1.0 / 87178291200.0, c16 = 1.0 / 20922789888000.0;
  const L ps = s3 + r2 * (s5 + r2 * (s7 + r2 * (s9 + r2 * (s11 + r2 * (s13 + r2 * (s15 + r2 * s17))))));
  const L pc = c2 + r2 * (c4 + r2 * (c6 + r2 * (c8 + r2 * (c10 + r2 * (c12 + r2 * (c14 + r2 * c16))))));
  const L sr = r + (r * r2) * ps, cr = 1.0 + r2 * pc;
  const M q = __builtin_convertvector(k, M);
  const M swap = (q & 1) != 0, sin_negative = (q & 2) != 0, cos_negative = ((q + 1) & 2) != 0;
  const L s = swap ? cr : sr, c = swap ? sr : cr;
  sin_x = sin_negative ? -s : s;
  cos_x = cos_negative ? -c : c;
}

// One variable (t): value, d/dt and, when S, d2/dt2.
template <bool S>
struct J1 {
  // NOTE: no zeroing by default (V3's members are value-initialised, and
  // the batch's many temporaries are all written before they are read:
  // zeroing them first is work for nothing in the inner loops).
  L v, d, h;
  J1() {}
  J1(L a, L b, L c) : v(a), d(b), h(c) {}
};

template <bool S>
ISOFORM_JET_INLINE J1<S> operator+(const J1<S>& a, const J1<S>& b) {
  return {a.v + b.v, a.d + b.d, S ? a.h + b.h : L{}};
}
template <bool S>
ISOFORM_JET_INLINE J1<S> operator-(const J1<S>& a, const J1<S>& b) {
  return {a.v - b.v, a.d - b.d, S ? a.h - b.h : L{}};
}
template <bool S>
ISOFORM_JET_INLINE J1<S> operator-(const J1<S>& a) {
  return {-a.v, -a.d, S ? -a.h : L{}};
}
template <bool S>
ISOFORM_JET_INLINE J1<S> operator*(const J1<S>& a, const J1<S>& b) {
  return {a.v * b.v, a.v * b.d + b.v * a.d, S ? a.v * b.h + b.v * a.h + 2.0 * a.d * b.d : L{}};
}
// A jet times a per-lane constant or a constant.
template <bool S>
ISOFORM_JET_INLINE J1<S> operator*(L c, const J1<S>& a) {
  return {c * a.v, c * a.d, S ? c * a.h : L{}};
}
template <bool S>
ISOFORM_JET_INLINE J1<S> operator*(double c, const J1<S>& a) {
  return {c * a.v, c * a.d, S ? c * a.h : L{}};
}
template <bool S>
ISOFORM_JET_INLINE J1<S> operator*(const J1<S>& a, double c) {
  return c * a;
}
template <bool S>
ISOFORM_JET_INLINE J1<S> operator+(const J1<S>& a, double c) {
  return {a.v + c, a.d, a.h};
}
template <bool S>
ISOFORM_JET_INLINE J1<S> operator+(double c, const J1<S>& a) {
  return a + c;
}
// f(x) given f, f', f'' at x.v.
template <bool S>
ISOFORM_JET_INLINE J1<S> chain(const J1<S>& x, L f0, L f1, L f2) {
  return {f0, f1 * x.d, S ? f1 * x.h + f2 * x.d * x.d : L{}};
}
template <bool S>
ISOFORM_JET_INLINE J1<S> reciprocal(const J1<S>& b) {
  const L inv = 1.0 / b.v;
  return chain(b, inv, -inv * inv, 2.0 * inv * inv * inv);
}
template <bool S>
ISOFORM_JET_INLINE J1<S> operator/(const J1<S>& a, const J1<S>& b) {
  // As jet1.h: q' = (a' - q b') / b, q'' = (a'' - 2 q' b' - q b'') / b.
  const L inv = 1.0 / b.v;
  J1<S> q;
  q.v = a.v * inv;
  q.d = (a.d - q.v * b.d) * inv;
  if constexpr (S) q.h = (a.h - 2.0 * q.d * b.d - q.v * b.h) * inv;
  return q;
}
template <bool S>
ISOFORM_JET_INLINE J1<S> sqrt(const J1<S>& x) {
  const L s = lane_sqrt(x.v);
  return chain(x, s, 0.5 / s, -0.25 / (s * x.v));
}
// Per lane: a where m, else b.
template <bool S>
ISOFORM_JET_INLINE J1<S> select(M m, const J1<S>& a, const J1<S>& b) {
  return {m ? a.v : b.v, m ? a.d : b.d, S ? (m ? a.h : b.h) : L{}};
}
template <bool S>
ISOFORM_JET_INLINE J1<S> zero1() {
  return {L{}, L{}, L{}};
}
template <bool S>
ISOFORM_JET_INLINE J1<S> abs(const J1<S>& x) {
  return select(x.v < 0.0, -x, x);
}

// Two variables (u, v): value, gradient and, when S, the Hessian
// (uu, uv, vv).
template <bool S>
struct J2 {
  L v, d[2], h[3];  // not zeroed: see J1
  J2() {}
};

template <bool S>
ISOFORM_JET_INLINE J2<S> operator+(const J2<S>& a, const J2<S>& b) {
  J2<S> r;
  r.v = a.v + b.v;
  for (int i = 0; i < 2; ++i) r.d[i] = a.d[i] + b.d[i];
  if constexpr (S)
    for (int i = 0; i < 3; ++i) r.h[i] = a.h[i] + b.h[i];
  return r;
}
template <bool S>
ISOFORM_JET_INLINE J2<S> operator*(const J2<S>& a, const J2<S>& b) {
  J2<S> r;
  r.v = a.v * b.v;
  for (int i = 0; i < 2; ++i) r.d[i] = a.v * b.d[i] + b.v * a.d[i];
  if constexpr (S) {
    r.h[0] = a.v * b.h[0] + b.v * a.h[0] + 2.0 * a.d[0] * b.d[0];
    r.h[1] = a.v * b.h[1] + b.v * a.h[1] + a.d[0] * b.d[1] + a.d[1] * b.d[0];
    r.h[2] = a.v * b.h[2] + b.v * a.h[2] + 2.0 * a.d[1] * b.d[1];
  }
  return r;
}
template <bool S>
ISOFORM_JET_INLINE J2<S> chain(const J2<S>& x, L f0, L f1, L f2) {
  J2<S> r;
  r.v = f0;
  r.d[0] = f1 * x.d[0];
  r.d[1] = f1 * x.d[1];
  if constexpr (S) {
    r.h[0] = f1 * x.h[0] + f2 * x.d[0] * x.d[0];
    r.h[1] = f1 * x.h[1] + f2 * x.d[0] * x.d[1];
    r.h[2] = f1 * x.h[2] + f2 * x.d[1] * x.d[1];
  }
  return r;
}
// As jet.h's division: a times the jet of 1 / b.
template <bool S>
ISOFORM_JET_INLINE J2<S> reciprocal(const J2<S>& b) {
  const L inv = 1.0 / b.v;
  return chain(b, inv, -inv * inv, 2.0 * inv * inv * inv);
}

}  // namespace isoform::patch::lanes
