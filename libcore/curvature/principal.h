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

}  // namespace isoform
