// Splitting a polygon face of a mesh file into triangles. The readers hand
// every face here, so a concave polygon becomes triangles that cover it
// without overlapping instead of a fan that folds over itself.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace isoform::meshio {

// Appends the triangles of the polygon whose corners are the vertex indices
// in corners, in order, to out as vertex-index triples; point gives a
// vertex's position. Every triangle turns the way the polygon does (its
// corners in the polygon's order).
//
// - 3 corners: the triangle itself. Fewer: nothing is appended.
// - The polygon is projected onto the coordinate plane most nearly parallel
//   to it (the plane that drops the largest coordinate of its Newell normal,
//   seen from the normal's side). Projected strictly convex (every corner a
//   left turn): the fan from corner 0, (0,1,2), (0,2,3), ..., in that order.
// - Otherwise ear clipping: of the corners whose triangle with its two
//   neighbours turns left and holds no other remaining corner (inside or on
//   its sides), the one whose triangle has the largest smallest angle is
//   cut off, the first in corner order on ties, until three corners remain.
// - The fan from corner 0 as well when the polygon has no plane (zero or
//   non-finite Newell normal, a position that is not finite, a projection
//   without positive area), when no ear can be found (which can happen to a
//   polygon that crosses or touches itself, or whose corners repeat a
//   position), and for polygons of more than kMostCornersToClip corners,
//   whose clipping could take too long (its time grows with the square of
//   the corner count). Nothing is lost then, and the mesh's own checks find
//   what is wrong with the result. A polygon that crosses itself may also
//   be clipped, or (turning left at every corner, as a five-pointed star
//   drawn in one stroke) taken for convex: its triangles overlap as the
//   fan's would, and the same checks report it.
//
// Never throws for geometric reasons; only std::bad_alloc, and what point
// throws, get out.
void split_polygon(const std::vector<int32_t>& corners,
                   const std::function<std::array<double, 3>(int32_t)>& point,
                   std::vector<int32_t>& out);

// Polygons with more corners are split into the fan without looking at them.
inline constexpr size_t kMostCornersToClip = 4096;

}  // namespace isoform::meshio
