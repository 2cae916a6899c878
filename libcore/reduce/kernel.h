// Beyond the seed: a point from which the platelet's boundary polygon is
// star-shaped. Theorem 5.3 asks that the new point's projection lie strictly
// left of every directed polygon edge (5.17); the points that do form the
// polygon's kernel, the intersection of those open half-planes. When neither
// the fitted point nor one of T's vertices passes, the kernel's centroid may:
// on real contours the polygon is often star-shaped, just not around them.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

namespace isoform::reduce {

// The centroid (of area) of the kernel of the closed polygon `ring`
// (counter-clockwise, 2D), each half-plane pulled in by `margin` times its
// edge's length; none when that kernel is empty or has no area.
std::optional<Eigen::Vector2d> kernel_centroid(const std::vector<Eigen::Vector2d>& ring, double margin);

}  // namespace isoform::reduce
