// A patch boundary: the conic along one mesh edge and the surface normal
// along it (Hamann 1991, Section 6.3 (i) and (6.13)-(6.16)). Built once per
// edge, from the lower to the higher vertex index, so both triangles that
// share the edge use the same curve and the same normals.
//
// Reading of (6.14)-(6.16): the normal n_S(t) is perpendicular to the
// curve's tangent T(t) (6.13) and is the conic's in-plane normal
// n_C(t) = p x T(t) turned about T(t) by a signed angle theta(t) that varies
// linearly from its value at t = 0 (where n_S = n0) to its value at t = 1
// (n_S = n3). The printed reading, a linear cosine gamma(t) (6.16), cannot
// be followed continuously: the conic's plane contains (n0 + n3) / 2, so n0
// and n3 make equal and opposite angles with the plane's normal, gamma(0) =
// gamma(1), the cosine is constant, and a normal that keeps it must jump
// (theta changes sign) where its out-of-plane part changes sign, which
// cracks the surface.
#pragma once

#include "conic.h"

namespace isoform::patch {

struct EdgeCurve {
  Conic<double> conic;
  double theta0 = 0.0, theta1 = 0.0;  // turn of n_S about T at t = 0 and t = 1
};

// The edge curve from (b0, n0) to (b3, n3); inv_tension as in make_conic.
EdgeCurve make_edge_curve(const V3d& b0, const V3d& n0, const V3d& b3, const V3d& n3, double inv_tension);

// Point and surface normal n_S at t of the edge (t = 0 at b0).
template <class T>
struct EdgeValue {
  V3<T> point, normal;
};

template <class T>
EdgeValue<T> edge_eval(const EdgeCurve& e, const T& t) {
  const Conic<T> c = lift<T>(e.conic);
  const ConicValue<T> cv = conic_eval(c, t);
  EdgeValue<T> r;
  r.point = cv.point;
  // NOTE: the end speed is positive (kFlatAngle), so T(t) is defined on [0, 1];
  // a degenerate (point) edge has none, and gets the interpolated angle
  // about a fixed frame instead.
  V3<T> tangent = cv.tangent;
  if (!(norm_value(tangent) > 0.0)) tangent = c.t0;
  const V3<T> T_unit = unit(tangent);
  const V3<T> nc = cross(c.p, T_unit);
  const T theta = (1.0 - t) * e.theta0 + t * e.theta1;
  r.normal = cos(theta) * nc + sin(theta) * c.p;
  return r;
}

}  // namespace isoform::patch
