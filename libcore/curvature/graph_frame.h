// The 4-D tangent space of the graph of a trivariate function at a point
// (Hamann 1991, Section 4.3, equations 4.42-4.46): the unit normal
// n = (-f_u, -f_v, -f_w, 1) / l, an orthonormal basis b1, b2, b3 of the
// tangent space by Gram-Schmidt from the first three axes of R^4, and the
// local coordinates (u, v, w) and signed distance d of a graph point.
#pragma once

#include <array>

namespace isoform {

using Vec4d = std::array<double, 4>;

struct GraphFrame {
  Vec4d n;                   // unit normal, last component positive
  std::array<Vec4d, 3> b;    // orthonormal tangent basis, each orthogonal to n
};

// The frame at a point where f has world gradient g.
GraphFrame graph_frame(const std::array<double, 3>& g);

// A graph point y_j relative to the frame's origin y_0, delta = y_j - y_0:
// its local coordinates (u, v, w) = (delta . b1, delta . b2, delta . b3)
// (4.45, 4.46; b_i is orthogonal to n, so projecting first (4.44) changes
// nothing) and its signed distance d = n . delta from the tangent space (4.43).
struct GraphLocal {
  double u, v, w, d;
};
GraphLocal graph_local(const GraphFrame& frame, const Vec4d& delta);

}  // namespace isoform
