// Forward-mode derivatives in two variables (u, v): a value with its gradient
// and, when Second is true, its Hessian. The side-vertex patch is evaluated
// with these in place of double, so its first and second derivatives (and
// with them the exact normal) come out of the same code that computes the
// point, with no difference quotients.
#pragma once

#include <cmath>

// NOTE: the jets' arithmetic is small and called millions of times per
// tessellation; GCC leaves it out of line at -O3, where each call costs
// more than the few operations it wraps, so it is forced inline.
#define ISOFORM_JET_INLINE __attribute__((always_inline)) inline

namespace isoform::patch {

template <bool Second>
struct Jet {
  double v = 0.0;
  double d[2] = {0.0, 0.0};       // d/du, d/dv
  double h[3] = {0.0, 0.0, 0.0};  // d2/du2, d2/dudv, d2/dv2 (when Second)

  Jet() = default;
  Jet(double value) : v(value) {}  // a constant (implicit, like a double)

  // The variable u (axis 0) or v (axis 1) at value x.
  static Jet variable(double x, int axis) {
    Jet j(x);
    j.d[axis] = 1.0;
    return j;
  }
};

// f(x) given f, f' and f'' at x.v.
template <bool S>
ISOFORM_JET_INLINE Jet<S> chain(const Jet<S>& x, double f0, double f1, double f2) {
  Jet<S> r(f0);
  r.d[0] = f1 * x.d[0];
  r.d[1] = f1 * x.d[1];
  if constexpr (S) {
    r.h[0] = f1 * x.h[0] + f2 * x.d[0] * x.d[0];
    r.h[1] = f1 * x.h[1] + f2 * x.d[0] * x.d[1];
    r.h[2] = f1 * x.h[2] + f2 * x.d[1] * x.d[1];
  }
  return r;
}

template <bool S>
ISOFORM_JET_INLINE Jet<S> operator+(const Jet<S>& a, const Jet<S>& b) {
  Jet<S> r(a.v + b.v);
  for (int i = 0; i < 2; ++i) r.d[i] = a.d[i] + b.d[i];
  if constexpr (S)
    for (int i = 0; i < 3; ++i) r.h[i] = a.h[i] + b.h[i];
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator-(const Jet<S>& a) {
  Jet<S> r(-a.v);
  for (int i = 0; i < 2; ++i) r.d[i] = -a.d[i];
  if constexpr (S)
    for (int i = 0; i < 3; ++i) r.h[i] = -a.h[i];
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator-(const Jet<S>& a, const Jet<S>& b) {
  return a + (-b);
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator*(const Jet<S>& a, const Jet<S>& b) {
  Jet<S> r(a.v * b.v);
  for (int i = 0; i < 2; ++i) r.d[i] = a.v * b.d[i] + b.v * a.d[i];
  if constexpr (S) {
    r.h[0] = a.v * b.h[0] + b.v * a.h[0] + 2.0 * a.d[0] * b.d[0];
    r.h[1] = a.v * b.h[1] + b.v * a.h[1] + a.d[0] * b.d[1] + a.d[1] * b.d[0];
    r.h[2] = a.v * b.h[2] + b.v * a.h[2] + 2.0 * a.d[1] * b.d[1];
  }
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator/(const Jet<S>& a, const Jet<S>& b) {
  const double inv = 1.0 / b.v;
  return a * chain(b, inv, -inv * inv, 2.0 * inv * inv * inv);
}
// Mixed forms with plain doubles.
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator+(const Jet<S>& a, double b) {
  Jet<S> r = a;
  r.v += b;
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator+(double a, const Jet<S>& b) {
  return b + a;
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator-(const Jet<S>& a, double b) {
  return a + (-b);
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator-(double a, const Jet<S>& b) {
  return (-b) + a;
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator*(const Jet<S>& a, double b) {
  Jet<S> r(a.v * b);
  for (int i = 0; i < 2; ++i) r.d[i] = a.d[i] * b;
  if constexpr (S)
    for (int i = 0; i < 3; ++i) r.h[i] = a.h[i] * b;
  return r;
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator*(double a, const Jet<S>& b) {
  return b * a;
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator/(const Jet<S>& a, double b) {
  return a * (1.0 / b);
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> operator/(double a, const Jet<S>& b) {
  return Jet<S>(a) / b;
}

template <bool S>
ISOFORM_JET_INLINE Jet<S> sqrt(const Jet<S>& x) {
  const double s = std::sqrt(x.v);
  return chain(x, s, 0.5 / s, -0.25 / (s * x.v));
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> sin(const Jet<S>& x) {
  const double s = std::sin(x.v), c = std::cos(x.v);
  return chain(x, s, c, -s);
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> cos(const Jet<S>& x) {
  const double s = std::sin(x.v), c = std::cos(x.v);
  return chain(x, c, -s, -c);
}
template <bool S>
ISOFORM_JET_INLINE Jet<S> abs(const Jet<S>& x) {
  return x.v < 0.0 ? -x : x;
}
// atan2(y, x) with both arguments jets.
template <bool S>
Jet<S> atan2(const Jet<S>& y, const Jet<S>& x) {
  const double r2 = x.v * x.v + y.v * y.v;
  const double ty = x.v / r2, tx = -y.v / r2;  // partials by y and by x
  Jet<S> r(std::atan2(y.v, x.v));
  for (int i = 0; i < 2; ++i) r.d[i] = ty * y.d[i] + tx * x.d[i];
  if constexpr (S) {
    const double r4 = r2 * r2;
    const double tyy = -2.0 * x.v * y.v / r4, txx = -tyy, txy = (y.v * y.v - x.v * x.v) / r4;
    const int a[3] = {0, 0, 1}, b[3] = {0, 1, 1};
    for (int k = 0; k < 3; ++k) {
      const int i = a[k], j = b[k];
      r.h[k] = ty * y.h[k] + tx * x.h[k] + tyy * y.d[i] * y.d[j] + txx * x.d[i] * x.d[j] +
               txy * (x.d[i] * y.d[j] + y.d[i] * x.d[j]);
    }
  }
  return r;
}

// The value of a jet or a double, for decisions (branches) only.
inline double value_of(double x) { return x; }
template <bool S>
ISOFORM_JET_INLINE double value_of(const Jet<S>& x) {
  return x.v;
}

}  // namespace isoform::patch
