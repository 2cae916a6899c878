// Forward-mode derivatives in one variable: a value with its first and, when
// Second is true, second derivative. The fast evaluation (fast_eval.h) builds
// each radial conic as a function of its one parameter t along the opposite
// edge with these (a third of the work of the two-variable jets of jet.h),
// and only then goes over to (u, v) by the chain rule.
#pragma once

#include <cmath>

#include "jet.h"

namespace isoform::patch {

template <bool Second>
struct Jet1 {
  double v = 0.0;
  double d = 0.0;  // d/dt
  double h = 0.0;  // d2/dt2 (when Second)

  Jet1() = default;
  Jet1(double value) : v(value) {}  // a constant (implicit, like a double)
  Jet1(double value, double d1, double d2) : v(value), d(d1), h(d2) {}

  static Jet1 variable(double x) { return Jet1(x, 1.0, 0.0); }
};

// f(x) given f, f' and f'' at x.v.
template <bool S>
ISOFORM_JET_INLINE Jet1<S> chain(const Jet1<S>& x, double f0, double f1, double f2) {
  Jet1<S> r(f0, f1 * x.d, 0.0);
  if constexpr (S) r.h = f1 * x.h + f2 * x.d * x.d;
  return r;
}

template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator+(const Jet1<S>& a, const Jet1<S>& b) {
  Jet1<S> r(a.v + b.v, a.d + b.d, 0.0);
  if constexpr (S) r.h = a.h + b.h;
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator-(const Jet1<S>& a) {
  Jet1<S> r(-a.v, -a.d, 0.0);
  if constexpr (S) r.h = -a.h;
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator-(const Jet1<S>& a, const Jet1<S>& b) {
  Jet1<S> r(a.v - b.v, a.d - b.d, 0.0);
  if constexpr (S) r.h = a.h - b.h;
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator*(const Jet1<S>& a, const Jet1<S>& b) {
  Jet1<S> r(a.v * b.v, a.v * b.d + b.v * a.d, 0.0);
  if constexpr (S) r.h = a.v * b.h + b.v * a.h + 2.0 * a.d * b.d;
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator/(const Jet1<S>& a, const Jet1<S>& b) {
  // q = a / b: q' = (a' - q b') / b, q'' = (a'' - 2 q' b' - q b'') / b.
  const double inv = 1.0 / b.v;
  Jet1<S> q(a.v * inv, 0.0, 0.0);
  q.d = (a.d - q.v * b.d) * inv;
  if constexpr (S) q.h = (a.h - 2.0 * q.d * b.d - q.v * b.h) * inv;
  return q;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator+(const Jet1<S>& a, double b) {
  Jet1<S> r = a;
  r.v += b;
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator+(double a, const Jet1<S>& b) {
  return b + a;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator-(const Jet1<S>& a, double b) {
  return a + (-b);
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator-(double a, const Jet1<S>& b) {
  return (-b) + a;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator*(const Jet1<S>& a, double b) {
  Jet1<S> r(a.v * b, a.d * b, 0.0);
  if constexpr (S) r.h = a.h * b;
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator*(double a, const Jet1<S>& b) {
  return b * a;
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator/(const Jet1<S>& a, double b) {
  return a * (1.0 / b);
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> operator/(double a, const Jet1<S>& b) {
  const double inv = 1.0 / b.v, q = a * inv;
  return chain(b, q, -q * inv, 2.0 * q * inv * inv);
}

template <bool S>
ISOFORM_JET_INLINE Jet1<S> sqrt(const Jet1<S>& x) {
  const double s = std::sqrt(x.v);
  return chain(x, s, 0.5 / s, -0.25 / (s * x.v));
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> sin(const Jet1<S>& x) {
  const double s = std::sin(x.v), c = std::cos(x.v);
  return chain(x, s, c, -s);
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> cos(const Jet1<S>& x) {
  const double s = std::sin(x.v), c = std::cos(x.v);
  return chain(x, c, -s, -c);
}
template <bool S>
ISOFORM_JET_INLINE Jet1<S> abs(const Jet1<S>& x) {
  return x.v < 0.0 ? -x : x;
}

template <bool S>
ISOFORM_JET_INLINE double value_of(const Jet1<S>& x) {
  return x.v;
}
// True when x is the constant 0 (value and derivatives).
inline bool is_zero(double x) { return x == 0.0; }
template <bool S>
ISOFORM_JET_INLINE bool is_zero(const Jet<S>& x) {
  return x.v == 0.0 && x.d[0] == 0.0 && x.d[1] == 0.0 && (!S || (x.h[0] == 0.0 && x.h[1] == 0.0 && x.h[2] == 0.0));
}
template <bool S>
ISOFORM_JET_INLINE bool is_zero(const Jet1<S>& x) {
  return x.v == 0.0 && x.d == 0.0 && (!S || x.h == 0.0);
}

}  // namespace isoform::patch
