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
// around q are the times it passes the ray from q through ring[0]; a closed
// polygon must pass it once (at ring[0] itself), an open corona's path
// (ring[0] .. ring[n - 1]) never, so that its fan sweeps less than a turn.
#pragma once

#include <Eigen/Core>

namespace isoform::reduce {

// q against the polygon ring[0 .. n), given by uv(j) (2D points,
// counter-clockwise), of which the first `edges` directed edges count
// (n for a closed polygon, n - 1 for an open path).
template <class UV>
bool half_plane_once(const Eigen::Vector2d& q, int n, int edges, UV&& uv) {
  if (n < 2) return false;
  const Eigen::Vector2d first = uv(0), a0 = first - q;
  Eigen::Vector2d yj = first;
  int turns = 0;
  for (int j = 0; j < edges; ++j) {
    const Eigen::Vector2d yk = uv((j + 1) % n);
    const Eigen::Vector2d d = yk - yj;
    // (5.17), with a relative margin, so that a point on the line (to
    // rounding) fails.
    const double l = -d(1) * (q(0) - yj(0)) + d(0) * (q(1) - yj(1));
    if (!(l > 1e-12 * d.squaredNorm())) return false;
    // Passing the ray through ring[0]: from below its line to on or above it.
    const Eigen::Vector2d a = yj - q, b = yk - q;
    const double below = a0(0) * a(1) - a0(1) * a(0), above = a0(0) * b(1) - a0(1) * b(0);
    turns += below < 0 && above >= 0 ? 1 : 0;
    yj = yk;
  }
  return turns == (edges == n ? 1 : 0);
}

}  // namespace isoform::reduce
