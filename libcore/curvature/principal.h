// Theorem 4.3 of Hamann (1991), generalised to a fitted height field with
// linear terms: the principal curvatures and directions at the origin of the
// graph x(u, v) = o + u b1 + v b2 + f(u, v) n.
//
// Sign: isoform reports curvature positive where the surface bends away from
// its normal, so a sphere with outward normals has k1 = k2 = 1/r. The seed's
// (4.31) measures the opposite sign (its roots are the eigenvalues of the
// second fundamental form taken along n); isoform's values are the seed's
// negated, and k1 >= k2 in isoform's sign.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "height_fit.h"

namespace isoform {

struct PrincipalCurvatures {
  double k1 = 0, k2 = 0;  // k1 >= k2
  Eigen::Vector3d d1{1, 0, 0}, d2{0, 1, 0};  // unit principal directions
  Eigen::Vector3d normal{0, 0, 1};            // unit normal of the fitted graph
  double mean() const { return 0.5 * (k1 + k2); }
  double gauss() const { return k1 * k2; }
};

// The frame's b1, b2, n must be orthonormal and right-handed.
PrincipalCurvatures principal_curvatures(const HeightFit& fit, const Eigen::Vector3d& b1,
                                         const Eigen::Vector3d& b2, const Eigen::Vector3d& n);

// principal_curvatures for four fits at once: out[l] is, bit for bit,
// principal_curvatures(f[l], b1[l], b2[l], n[l]) (principal_lanes.h).
void principal_curvatures4(const HeightFit (&f)[4], const Eigen::Vector3d (&b1)[4], const Eigen::Vector3d (&b2)[4],
                           const Eigen::Vector3d (&n)[4], PrincipalCurvatures (&out)[4]);

// principal_curvatures' body, inline: a caller whose fit has no linear terms
// (fu = fv = 0 known to the compiler) gets the steps that are exact for them
// folded away, with the same bits.
// t scaled to unit length by one reciprocal (t itself where it is zero).
inline __attribute__((always_inline)) Eigen::Vector3d unit(const Eigen::Vector3d& t) {
  const double z = (t(0) * t(0) + t(1) * t(1)) + t(2) * t(2);
  if (!(z > 0.0)) return t;
  const double inv = 1.0 / std::sqrt(z);
  return {t(0) * inv, t(1) * inv, t(2) * inv};
}

inline __attribute__((always_inline)) PrincipalCurvatures principal_curvatures_inline(const HeightFit& f, const Eigen::Vector3d& b1,
                                                       const Eigen::Vector3d& b2, const Eigen::Vector3d& n) {
  PrincipalCurvatures pc;
  const double l = std::sqrt(1.0 + f.fu * f.fu + f.fv * f.fv);
  // First fundamental form E F G, and the second along the graph's normal,
  // negated for isoform's sign (positive where the surface bends away).
  const double E = 1.0 + f.fu * f.fu, F = f.fu * f.fv, G = 1.0 + f.fv * f.fv;
  // Divisions are few: each divisor's reciprocal once, then products.
  const double inv_l = 1.0 / l;
  const double L = -f.fuu * inv_l, M = -f.fuv * inv_l, N = -f.fvv * inv_l;
  // The shape operator W = I^-1 II; its trace and determinant give H and K.
  const double det_i = E * G - F * F;
  const double inv_det = 1.0 / det_i;
  const double w11 = (G * L - F * M) * inv_det, w12 = (G * M - F * N) * inv_det;
  const double w21 = (E * M - F * L) * inv_det, w22 = (E * N - F * M) * inv_det;
  const double h = 0.5 * (w11 + w22), k = w11 * w22 - w12 * w21;
  const double disc = std::sqrt(std::max(0.0, h * h - k));
  pc.k1 = h + disc;
  pc.k2 = h - disc;
  const Eigen::Vector3d xu = b1 + f.fu * n, xv = b2 + f.fv * n;
  pc.normal = (n - f.fu * b1 - f.fv * b2) * inv_l;
  // The eigenvector of W for k1 from whichever row of (W - k1 I) is larger;
  // at an umbilic every direction is principal.
  // (Squared lengths: the comparisons are those of the lengths.)
  const double a1 = w11 - pc.k1, a2 = w22 - pc.k1;
  const double r1 = a1 * a1 + w12 * w12, r2 = w21 * w21 + a2 * a2;
  const double tiny = 1e-12 * (std::abs(pc.k1) + std::abs(pc.k2) + 1e-300);
  Eigen::Vector2d e;
  if (std::max(r1, r2) <= tiny * tiny)
    e = {1.0, 0.0};
  else if (r1 >= r2)
    e = {w12, pc.k1 - w11};
  else
    e = {pc.k1 - w22, w21};
  pc.d1 = unit(e(0) * xu + e(1) * xv);
  pc.d2 = unit(pc.normal.cross(pc.d1));
  return pc;
}

}  // namespace isoform
