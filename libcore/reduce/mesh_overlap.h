// Self-overlap of a triangle mesh: every pair of triangles that intersect
// beyond the vertices they share (triangle_overlap.h). The broad phase is a
// uniform grid, hashed: each triangle's bounding box is entered in
// the cells it covers (cell size the mean box size), and a pair whose boxes
// overlap is tested once, in the cell of the low corner of their common box.
// A triangle covering more cells than n / 32 (a ground quad under a detailed
// model) stays out of the grid and is tested against every triangle's box.
// About O(n) on surfaces whose triangles are of similar size; parallel (TBB).
#pragma once

#include <cstdint>
#include <vector>

#include "../mesh.h"
#include "triangle_overlap.h"

namespace isoform::reduce {

struct OverlapPair {
  int32_t a = 0, b = 0;  // triangle indices, a < b
  Point3 near{};         // a point of (or near) their intersection
};

// All overlapping pairs, sorted by (a, b). Uses the precise points when the
// mesh has them. Every index must name a vertex; triangles with a corner that
// is not finite are left out (the caller refuses those first).
std::vector<OverlapPair> find_overlaps(const Mesh& mesh);

}  // namespace isoform::reduce
