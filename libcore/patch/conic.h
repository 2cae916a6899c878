// The conic curve scheme of Hamann (1991), Section 6.2: a planar rational
// cubic through b0 and b3 that is tangent there to the planes of the normals
// n0 and n3, the degree elevation of a conic (convex data) or a cubic with an
// inflection (non-convex data, Definition 6.3). Written as a template over the
// scalar (double or a Jet, jet.h) so the patch gets exact derivatives.
//
// Readings of Chapter 6 taken here:
// - The cubic's interior weights are (1 + 2 omega) / 3, the degree elevation
//   of the quadratic conic with weight omega that (6.8) and Theorem 6.3 speak
//   of; (6.5) printed omega itself, which read literally gives no circles
//   and a straight segment for parallel tangents.
// - omega = sin(gamma / 2) (Theorem 6.3) and L01 from (6.9) are combined
//   into L01 = L sin(beta) / ((1 + 2 omega) cos(gamma / 2)), the same number
//   with the 0/0 of (6.12) cancelled, so parallel tangents need no branch.
// - Non-convex data: the tangents reflected in the chord give a convex
//   triangle with the angles |alpha|, |beta|; the interior points take its
//   lengths along the actual tangents, b1 = b0 + L01 t0, b2 = b3 - L23 t3,
//   continuous in the angles (both readings agree where a tangent lies on the
//   chord).
// - Tension: a user weight W (inv_tension = 1 / W; 0 means automatic) gives
//   omega = W a / sqrt(W^2 + a^2) with a = sin(gamma / 2): W where W << a,
//   never more than a, so Theorem 6.3's finite limit still holds.
#pragma once

#include <cstdint>

#include "vec3.h"

namespace isoform::patch {

// What the construction met (bits of Conic::flags).
enum ConicFlag : uint8_t {
  kConicNonConvex = 1,       // Definition 6.3: an inflection
  kConicOppositeNormals = 2, // n0 = -n3: plane from the chord and n0
  kConicFallbackPlane = 4,   // no plane from the data: any plane through the chord
  kConicDegenerate = 8,      // b0 = b3: a point
};

template <class T>
struct Conic {
  V3<T> b[4];    // Bezier points
  T w{};         // weight of b1 and b2 (b0, b3 have weight 1)
  V3<T> p;       // unit normal of the conic plane P
  V3<T> t0, t3;  // unit end tangents, in the direction of travel
  uint8_t flags = 0;
};

// NOTE: the lengths (6.9) depend on the ratios sin(beta) / cos(gamma/2) and
// sin(alpha) / cos(gamma/2), which tend to 2 beta / (alpha + beta) as the data
// become straight: a limit that depends on the ratio of two vanishing angles,
// so float noise in nearly equal normals (flat parts of a contour) throws the
// interior points anywhere between the ends and the curve's end speed to
// zero. Both ratios are taken as (sin + kFlatAngle) / (cos(gamma/2) +
// kFlatAngle): unchanged for isosceles data (circles stay exact), the
// straight limit becomes the uniform one (ratio 1), and for angles well above
// kFlatAngle radians the change is below kFlatAngle / angle relative.
constexpr double kFlatAngle = 1e-4;

namespace detail {

// A unit normal of a plane through the chord d (unit), containing m if it
// can; sets flags when the data do not define the plane.
template <class T>
V3<T> conic_plane(const V3<T>& dh, const V3<T>& n0, const V3<T>& n3, uint8_t& flags) {
  V3<T> m = n0 + n3;
  // NOTE: relative to |n| = 1; below this n0 and n3 are taken as opposite.
  if (norm_value(m) < 1e-9) {
    flags |= kConicOppositeNormals;
    m = n0 - dot(n0, dh) * dh;
  }
  V3<T> pc = cross(dh, m);
  if (norm_value(pc) < 1e-12) {
    flags |= kConicFallbackPlane;
    const V3d a = values(dh);
    const V3d axis = std::abs(a.x) <= std::abs(a.y) && std::abs(a.x) <= std::abs(a.z)
                         ? V3d(1, 0, 0)
                         : (std::abs(a.y) <= std::abs(a.z) ? V3d(0, 1, 0) : V3d(0, 0, 1));
    pc = cross(dh, V3<T>::from(axis));
  }
  return unit(pc);
}

// The unit tangent n x p; p itself if n is parallel to p (no tangent plane
// meets P in a line), which only a fallback plane can cause.
template <class T>
V3<T> end_tangent(const V3<T>& n, const V3<T>& p, const V3<T>& dh) {
  const V3<T> t = cross(n, p);
  if (norm_value(t) < 1e-12) return dh;
  return unit(t);
}

// cos and sin of half the angle in [0, pi] whose cosine is c and sine
// s >= 0 (c^2 + s^2 = 1), without atan2: the square root is taken of the
// term that stays away from 0, so its derivatives are finite.
template <class T>
ISOFORM_JET_INLINE void half_angle(const T& c, const T& s, T& ch, T& sh) {
  if (value_of(c) >= 0.0) {
    ch = sqrt(0.5 + 0.5 * c);
    sh = s / (2.0 * ch);
  } else {
    sh = sqrt(0.5 - 0.5 * c);
    ch = s / (2.0 * sh);
  }
}

}  // namespace detail

template <class T>
Conic<T> make_conic(const V3<T>& b0, const V3<T>& n0, const V3<T>& b3, const V3<T>& n3,
                    const T& inv_tension) {
  Conic<T> c;
  c.b[0] = b0;
  c.b[3] = b3;
  const V3<T> d = b3 - b0;
  const T len = norm(d);
  if (!(value_of(len) > 0.0)) {
    c.b[1] = c.b[2] = b0;
    c.w = T(1.0);
    c.flags = kConicDegenerate;
    c.p = V3<T>(T(0.0), T(0.0), T(1.0));
    c.t0 = c.t3 = V3<T>(T(1.0), T(0.0), T(0.0));
    return c;
  }
  const V3<T> dh = (T(1.0) / len) * d;
  // (i) the plane P; (ii) the tangents where P meets the tangent planes.
  c.p = detail::conic_plane(dh, n0, n3, c.flags);
  c.t0 = detail::end_tangent(n0, c.p, dh);
  c.t3 = detail::end_tangent(n3, c.p, dh);
  // Angles with the chord in P's frame (dh, e); e points to n's side.
  const V3<T> e = cross(c.p, dh);
  const T s0 = dot(c.t0, e), s3 = dot(c.t3, e);
  if (value_of(s0) * value_of(s3) > 0.0) c.flags |= kConicNonConvex;
  const T sin_alpha = abs(s0), sin_beta = abs(s3);
  T ca, sa, cb, sb;  // cos and sin of alpha / 2 and beta / 2
  detail::half_angle(dot(c.t0, dh), sin_alpha, ca, sa);
  detail::half_angle(dot(c.t3, dh), sin_beta, cb, sb);
  // gamma = pi - alpha - beta: sin(gamma/2) = cos(h), cos(gamma/2) = sin(h)
  // with h = (alpha + beta) / 2.
  T a = ca * cb - sa * sb;
  if (value_of(a) < 0.0) a = T(0.0);  // tangent lines meet behind the chord
  // NOTE: automatic weights (inv_tension the constant 0) give q = 1 exactly.
  const T q = is_zero(inv_tension) ? T(1.0) : 1.0 / sqrt(1.0 + (a * inv_tension) * (a * inv_tension));
  const T omega = q * a;
  const T cos_half_gamma = sa * cb + ca * sb;
  const T inv_den = 1.0 / (cos_half_gamma + kFlatAngle);
  const T ratio_0 = (sin_beta + kFlatAngle) * inv_den, ratio_3 = (sin_alpha + kFlatAngle) * inv_den;
  const T scale = q * len / (1.0 + 2.0 * omega);
  c.b[1] = b0 + (scale * ratio_0) * c.t0;
  c.b[2] = b3 - (scale * ratio_3) * c.t3;
  c.w = (1.0 + 2.0 * omega) / 3.0;
  return c;
}

// Point and first derivative of the rational cubic at t in [0, 1].
template <class T>
struct ConicValue {
  V3<T> point, tangent;
};

template <class T>
ConicValue<T> conic_eval(const Conic<T>& c, const T& t) {
  const T s = 1.0 - t;
  // Bernstein basis times weights, and their derivatives.
  const T B[4] = {s * s * s, 3.0 * s * s * t * c.w, 3.0 * s * t * t * c.w, t * t * t};
  const T dB[4] = {-3.0 * s * s, 3.0 * c.w * (s * s - 2.0 * s * t), 3.0 * c.w * (2.0 * s * t - t * t),
                   3.0 * t * t};
  V3<T> num = B[0] * c.b[0] + B[1] * c.b[1] + B[2] * c.b[2] + B[3] * c.b[3];
  V3<T> dnum = dB[0] * c.b[0] + dB[1] * c.b[1] + dB[2] * c.b[2] + dB[3] * c.b[3];
  const T den = B[0] + B[1] + B[2] + B[3];
  const T dden = dB[0] + dB[1] + dB[2] + dB[3];
  const T inv = 1.0 / den;
  ConicValue<T> r;
  r.point = inv * num;
  r.tangent = inv * (dnum - dden * r.point);
  return r;
}

// Only the point (cheaper: no derivative).
template <class T>
V3<T> conic_point(const Conic<T>& c, const T& t) {
  const T s = 1.0 - t;
  const T B[4] = {s * s * s, 3.0 * s * s * t * c.w, 3.0 * s * t * t * c.w, t * t * t};
  const V3<T> num = B[0] * c.b[0] + B[1] * c.b[1] + B[2] * c.b[2] + B[3] * c.b[3];
  return (1.0 / (B[0] + B[1] + B[2] + B[3])) * num;
}

// A conic of doubles as a conic over T (constants for the jets).
template <class T>
Conic<T> lift(const Conic<double>& c) {
  Conic<T> r;
  for (int i = 0; i < 4; ++i) r.b[i] = V3<T>::from(c.b[i]);
  r.w = T(c.w);
  r.p = V3<T>::from(c.p);
  r.t0 = V3<T>::from(c.t0);
  r.t3 = V3<T>::from(c.t3);
  r.flags = c.flags;
  return r;
}

}  // namespace isoform::patch
