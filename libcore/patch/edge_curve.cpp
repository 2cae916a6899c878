// Edge curves of the side-vertex patch (Section 6.3 (i), (6.13)-(6.16)).
#include "edge_curve.h"

namespace isoform::patch {
namespace {

// The signed turn about the end tangent t that takes p x t to n: n is
// perpendicular to t (t = n x p), so n = cos(theta) (p x t) + sin(theta) p.
double turn(const V3d& n, const V3d& p, const V3d& t) {
  return std::atan2(dot(n, p), dot(n, cross(p, t)));
}

}  // namespace

EdgeCurve make_edge_curve(const V3d& b0, const V3d& n0, const V3d& b3, const V3d& n3, double inv_tension) {
  EdgeCurve e;
  e.conic = make_conic(b0, n0, b3, n3, inv_tension);
  e.theta0 = turn(n0, e.conic.p, e.conic.t0);
  e.theta1 = turn(n3, e.conic.p, e.conic.t3);
  return e;
}

}  // namespace isoform::patch
