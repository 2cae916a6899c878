// Theorem 5.3 of Hamann (1991), the planar half-plane test (5.17), for the
// point that will be inserted, and beyond the seed: the platelet polygon
// goes around that point once.
//
// NOTE: (5.17) asks only that the point q lie strictly left of every directed
// polygon edge, which makes every fan triangle turn counter-clockwise in the
// plane P. A polygon that winds twice around q (a platelet folded round in
// its projection onto T's plane: seen on real contours, about one removal in
// ten thousand on the bench's CT contour) passes too, and its fan covers
// the plane around q twice: the new triangles overlap in P, and mostly in
// space. Each edge subtends an angle in (0, pi) at q, so the polygon's turns
// are counted as its passes of the ray from q along +u: an edge from below
// q's line (v < q_v) to on or above it meets the line on the ray's side.
// A closed polygon must pass it once; an open corona's path (ring[0] ..
// ring[n - 1]), whose fan sweeps from its first corner to its last, never,
// or once and end at a smaller angle than it starts (less than a turn).
// NOTE: the sides are exact comparisons of v coordinates, each corner's made
// once for both its edges: a corner on the line (to rounding) is passed
// once, whichever side it is given, so the count is the polygon's winding
// number wherever (5.17) holds with its margin. (A ray through ring[0] puts
// that corner on it; a corner just after it, below it by rounding, counted
// a second pass.)
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace isoform::reduce {

// q against the polygon ring[0 .. n), given by uv(j) (2D points,
// counter-clockwise), of which the first `edges` directed edges count
// (n for a closed polygon, n - 1 for an open path).
template <class UV>
bool half_plane_once(const Eigen::Vector2d& q, int n, int edges, UV&& uv) {
  if (edges <= 0) return true;  // (no edge: nothing to test, as with (5.17) alone)
  const Eigen::Vector2d first = uv(0);
  Eigen::Vector2d yj = first;
  int passes = 0;
  for (int j = 0; j < edges; ++j) {
    const Eigen::Vector2d yk = uv((j + 1) % n);
    const Eigen::Vector2d d = yk - yj;
    // (5.17), with a relative margin, so that a point on the line (to
    // rounding) fails.
    const double l = -d(1) * (q(0) - yj(0)) + d(0) * (q(1) - yj(1));
    if (!(l > 1e-12 * d.squaredNorm())) return false;
    passes += yj(1) < q(1) && yk(1) >= q(1) ? 1 : 0;
    yj = yk;
  }
  if (edges == n) return passes == 1;
  if (passes != 1) return passes == 0;
  // The angle of a corner around q from +u, in [0, 2 pi), on the same side
  // of q's line as the passes took it.
  const auto angle = [&](const Eigen::Vector2d& y) {
    const double a = std::atan2((y(1) - q(1)) + 0.0, y(0) - q(0));  // (+ 0.0: no -0)
    return y(1) < q(1) ? (a < 0 ? a + 2 * M_PI : a) : std::max(a, 0.0);
  };
  return angle(yj) < angle(first);
}

}  // namespace isoform::reduce
