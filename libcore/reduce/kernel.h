// Beyond the seed: a point from which the platelet's boundary polygon is
// star-shaped. Theorem 5.3 asks that the new point's projection lie strictly
// left of every directed polygon edge (5.17); the points that do form the
// polygon's kernel, the intersection of those open half-planes. When neither
// the fitted point nor one of T's vertices passes, a point of the kernel may:
// on real contours the polygon is often star-shaped, just not around them.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

namespace isoform::reduce {

// The kernel of the closed polygon `ring` (counter-clockwise, 2D), each
// half-plane pulled in by `margin` times its edge's length, as a convex
// polygon (counter-clockwise); empty when that kernel is empty or has no
// area.
std::vector<Eigen::Vector2d> polygon_kernel(const std::vector<Eigen::Vector2d>& ring, double margin);

// The centroid (of area) of a convex polygon; none when it has no area.
std::optional<Eigen::Vector2d> convex_centroid(const std::vector<Eigen::Vector2d>& polygon);

// The centroid of the kernel of `ring` (polygon_kernel); none when the
// kernel is empty.
std::optional<Eigen::Vector2d> kernel_centroid(const std::vector<Eigen::Vector2d>& ring, double margin);

// The point of the kernel of `ring` chosen for q (the fitted point's
// projection): when q lies outside the kernel, its nearest point on the
// kernel's boundary moved a quarter of the way to the kernel's centroid (so
// that the new point stays as near its fitted surface as the polygon
// allows); else the centroid. None when the kernel is empty.
std::optional<Eigen::Vector2d> kernel_point(const std::vector<Eigen::Vector2d>& ring, double margin,
                                            const Eigen::Vector2d& q);

}  // namespace isoform::reduce
