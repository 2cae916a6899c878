// Section 5.2 of Hamann (1991): the point p that replaces a removed triangle
// T, and its curvature. The plane P of T carries a frame (5.9-5.11) with the
// corona's origin c; either a bivariate quadratic d = f(u, v) is fitted to
// the platelet's vertices by least squares (5.26-5.28) and p = c + f(0,0) n
// (5.29), with the curvature of Theorem 5.5; or an implicit quadric is
// fitted (5.30-5.32, Remark 5.6 with few points) and cut by the line c + t n
// (5.33), with the curvature of Theorem 5.6.
#pragma once

#include <Eigen/Core>

#include "platelet.h"
#include "reduce.h"

namespace isoform::reduce {

// The plane of T: unit normal n (outward, from the winding), b1 along the
// first edge, b2 = n x b1, origin c.
struct Frame {
  Eigen::Vector3d c, b1, b2, n;
  Eigen::Vector2d uv(const Eigen::Vector3d& x) const { return {(x - c).dot(b1), (x - c).dot(b2)}; }
};

struct Replacement {
  bool ok = false;                  // false: T is degenerate (no plane)
  Eigen::Vector3d point{0, 0, 0};
  Eigen::Vector3d normal{0, 0, 1};  // unit normal of the fitted surface at point
  double k1 = 0, k2 = 0;            // isoform's sign (positive bending away from normal)
  Eigen::Vector3d d1{1, 0, 0}, d2{0, 1, 0};
  int fit_terms = 0;                // coefficients actually fitted (0: p = c)
};

Frame platelet_frame(const WorkMesh& w, const Platelet& p, bool* ok);

// The replacement point of T. With keep_xy (graph mode, open corona) the
// point on the fitted surface above c's (x, y) is taken instead of the one
// along n, so that a boundary point stays on the domain's boundary.
Replacement replacement_point(const WorkMesh& w, const Platelet& p, const Frame& frame, ReducePoint method,
                              bool keep_xy);

}  // namespace isoform::reduce
