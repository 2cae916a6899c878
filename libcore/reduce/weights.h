// Section 5.2 of Hamann (1991): the weights that order the triangles. The
// angle weight sigma (5.21) is 1 for an equilateral triangle and 0 for a
// degenerate one (Lemma 5.1); the curvature weight rho (5.22) sums the
// absolute curvatures |k1| + |k2| (5.19) at the vertices; omega = sigma rho
// (5.23). The lightest triangle is removed first.
#pragma once

#include <Eigen/Core>

namespace isoform::reduce {

double angle_weight(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2);

inline double triangle_weight(double sigma, double a0, double a1, double a2) { return sigma * (a0 + a1 + a2); }

}  // namespace isoform::reduce
