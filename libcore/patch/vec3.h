// Three-vectors over double or a Jet (jet.h), for the conic scheme and the
// patch, which are written once as templates over their scalar.
#pragma once

#include <array>
#include <cmath>

#include "jet.h"
#include "jet1.h"

namespace isoform::patch {

using std::abs;
using std::atan2;
using std::cos;
using std::sin;
using std::sqrt;

template <class T>
struct V3 {
  T x{}, y{}, z{};
  V3() = default;
  V3(T a, T b, T c) : x(a), y(b), z(c) {}
  // A constant vector as a jet vector (or a double vector as itself).
  template <class U>
  static V3 from(const V3<U>& o) {
    return V3(T(o.x), T(o.y), T(o.z));
  }
  static V3 from(const std::array<double, 3>& a) { return V3(T(a[0]), T(a[1]), T(a[2])); }
};

using V3d = V3<double>;

template <class T>
ISOFORM_JET_INLINE V3<T> operator+(const V3<T>& a, const V3<T>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
ISOFORM_JET_INLINE V3<T> operator-(const V3<T>& a, const V3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
ISOFORM_JET_INLINE V3<T> operator-(const V3<T>& a) {
  return {-a.x, -a.y, -a.z};
}
template <class T, class S>
ISOFORM_JET_INLINE V3<T> operator*(const S& s, const V3<T>& a) {
  return {a.x * s, a.y * s, a.z * s};
}
template <class T>
ISOFORM_JET_INLINE T dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
ISOFORM_JET_INLINE V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
ISOFORM_JET_INLINE T norm(const V3<T>& a) {
  return sqrt(dot(a, a));
}
template <class T>
ISOFORM_JET_INLINE double norm_value(const V3<T>& a) {
  const double x = value_of(a.x), y = value_of(a.y), z = value_of(a.z);
  return std::sqrt(x * x + y * y + z * z);
}
// a / |a|; the caller makes sure |a| > 0.
template <class T>
ISOFORM_JET_INLINE V3<T> unit(const V3<T>& a) {
  const T n = norm(a);
  return (T(1.0) / n) * a;
}
template <class T>
ISOFORM_JET_INLINE V3<double> values(const V3<T>& a) {
  return {value_of(a.x), value_of(a.y), value_of(a.z)};
}

}  // namespace isoform::patch
