// Section 5.2 of Hamann (1991): the weights that order the triangles. The
// angle weight sigma (5.21) is 1 for an equilateral triangle and 0 for a
// degenerate one (Lemma 5.1); the curvature weight rho (5.22) sums the
// absolute curvatures |k1| + |k2| (5.19) at the vertices; omega = sigma rho
// (5.23). The lightest triangle is removed first.
#pragma once

#include <algorithm>

#include <Eigen/Core>

namespace isoform::reduce {

// NOTE: inline: the swaps, the new faces' weights and the queue call it
// millions of times a reduction, from three files.
inline double angle_weight(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2) {
  const Eigen::Vector3d e0 = x1 - x0, e1 = x2 - x1, e2 = x0 - x2;
  const double l0 = e0.norm(), l1 = e1.norm(), l2 = e2.norm();
  if (!(l0 > 0 && l1 > 0 && l2 > 0)) return 0.0;
  // cos of the interior angle at each vertex, from its two edges.
  const double c0 = -e2.dot(e0) / (l2 * l0), c1 = -e0.dot(e1) / (l0 * l1), c2 = -e1.dot(e2) / (l1 * l2);
  return std::clamp(2.0 * (c0 + c1 + c2 - 1.0), 0.0, 1.0);
}

inline double triangle_weight(double sigma, double a0, double a1, double a2) { return sigma * (a0 + a1 + a2); }

}  // namespace isoform::reduce
