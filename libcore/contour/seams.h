// The global half of the brick-by-brick topology (brick_topology.h): edges
// on brick boundaries matched across bricks, and parts joined across them
// and numbered by size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "brick_topology.h"

namespace isoform {

// Sorts the seam edges by key, then edge (seams must come with their edges
// increasing, as merge.cpp writes them, and with the vertices of their keys
// below vertex_count), and fills their neighbours as compute_neighbours
// would: an edge held by exactly two triangles makes them neighbours (and
// appends the pair to links), one held by one is a boundary edge, one held
// by three or more gets no neighbours and counts as non-manifold.
// Runs in parallel with TBB in the calling task arena.
void match_seams(SeamEdge* seams, size_t n, size_t vertex_count, const std::vector<int32_t>& triangles,
                 std::vector<int32_t>& neighbours, TopologyCounts& counts,
                 std::vector<std::pair<int32_t, int32_t>>& links);

// parts holds each triangle's brick-local part, made global (0 ..
// local_parts - 1, increasing with the part's first triangle). Joins the
// local parts that links connect and rewrites parts with the final labels,
// numbered by size, largest first, ties by first triangle, as compute_parts
// does. Returns the number of parts.
int32_t number_parts(std::vector<int32_t>& parts, size_t local_parts,
                     const std::vector<std::pair<int32_t, int32_t>>& links);

}  // namespace isoform
