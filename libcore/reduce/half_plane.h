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
// around q are the times it passes a ray from q: a closed polygon must pass
// the ray along +u once, an open corona's path (ring[0] .. ring[n - 1])
// never pass the ray through ring[0], so that its fan sweeps less than a
// turn.
// NOTE: a fixed ray for closed polygons: each corner's side of it is
// computed once for the two edges that meet there, so a corner on the ray
// (to rounding) is passed once whichever side it is given. The ray through
// ring[0] would put ring[0] on it exactly and a corner just after it
// possibly below it by rounding: two passes, and a false refusal. (An open
// path has no other ray to take; there the same rounding can only refuse.)
#pragma once

#include <Eigen/Core>

namespace isoform::reduce {

// q against the polygon ring[0 .. n), given by uv(j) (2D points,
// counter-clockwise), of which the first `edges` directed edges count
// (n for a closed polygon, n - 1 for an open path).
template <class UV>
bool half_plane_once(const Eigen::Vector2d& q, int n, int edges, UV&& uv) {
  if (n < 2) return false;
  const bool closed = edges == n;
  const Eigen::Vector2d first = uv(0);
  // The ray's direction: +u, or (open) towards ring[0].
  const Eigen::Vector2d r = closed ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(first - q);
  Eigen::Vector2d yj = first;
  double side_j = r(0) * (yj(1) - q(1)) - r(1) * (yj(0) - q(0));  // > 0: left of the ray's line
  int turns = 0;
  for (int j = 0; j < edges; ++j) {
    const Eigen::Vector2d yk = uv((j + 1) % n);
    const Eigen::Vector2d d = yk - yj;
    // (5.17), with a relative margin, so that a point on the line (to
    // rounding) fails.
    const double l = -d(1) * (q(0) - yj(0)) + d(0) * (q(1) - yj(1));
    if (!(l > 1e-12 * d.squaredNorm())) return false;
    // Passing the ray: from right of its line to on or left of it (with q
    // left of the edge, such an edge meets the line on the ray's side).
    const double side_k = r(0) * (yk(1) - q(1)) - r(1) * (yk(0) - q(0));
    turns += side_j < 0 && side_k >= 0 ? 1 : 0;
    yj = yk;
    side_j = side_k;
  }
  return turns == (closed ? 1 : 0);
}

}  // namespace isoform::reduce
