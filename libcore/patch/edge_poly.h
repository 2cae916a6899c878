// An edge curve (edge_curve.h) in the form the fast evaluation wants, made
// once per edge when the surface is built: the rational cubic's numerator
// (weighted Bezier points) and denominator as polynomials in t, so a point
// with its first three derivatives is two Horner sweeps, and the constants
// of the boundary normal (6.13)-(6.16), continuous reading.
#pragma once

#include "edge_curve.h"

namespace isoform::patch {

struct EdgePoly {
  V3d num[4];       // numerator: sum of num[k] t^k
  double den[4]{};  // denominator: sum of den[k] t^k
  V3d p, t0;        // conic plane's unit normal; start tangent (fallback)
  double theta0 = 0.0, dtheta = 0.0;  // turn of n_S about T: theta0 + t dtheta
};

inline EdgePoly make_edge_poly(const EdgeCurve& e) {
  const Conic<double>& c = e.conic;
  const double w[4] = {1.0, c.w, c.w, 1.0};
  V3d h[4];
  for (int k = 0; k < 4; ++k) h[k] = w[k] * c.b[k];
  // Bernstein to power basis.
  EdgePoly r;
  r.num[0] = h[0];
  r.num[1] = 3.0 * (h[1] - h[0]);
  r.num[2] = 3.0 * (h[2] - 2.0 * h[1] + h[0]);
  r.num[3] = h[3] - 3.0 * h[2] + 3.0 * h[1] - h[0];
  r.den[0] = w[0];
  r.den[1] = 3.0 * (w[1] - w[0]);
  r.den[2] = 3.0 * (w[2] - 2.0 * w[1] + w[0]);
  r.den[3] = w[3] - 3.0 * w[2] + 3.0 * w[1] - w[0];
  r.p = c.p;
  r.t0 = c.t0;
  r.theta0 = e.theta0;
  r.dtheta = e.theta1 - e.theta0;
  return r;
}

}  // namespace isoform::patch
