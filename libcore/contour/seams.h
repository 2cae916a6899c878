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
// below vertex_count; a radix sort by the smaller vertex, then each run of
// one smaller vertex in key order), and fills their neighbours as compute_neighbours
// would: an edge held by exactly two triangles makes them neighbours (and
// appends the pair of their parts to links, unless the parts are one or
// the pair was the last one appended), one held by one is a boundary edge,
// one held by three or more gets no neighbours and counts as non-manifold.
// parts: each triangle's local part (number_parts). Runs in parallel with
// TBB in the calling task arena.
void match_seams(SeamEdge* seams, size_t n, size_t vertex_count, std::vector<int32_t>& neighbours,
                 const std::vector<int32_t>& parts, TopologyCounts& counts,
                 std::vector<std::pair<int32_t, int32_t>>& links);

// parts holds each triangle's brick-local part, made global (0 ..
// local_parts - 1, increasing with the part's first triangle), size the
// triangles of each local part (local_parts of them). Joins the local
// parts that links (pairs of local parts) connect and rewrites parts with
// the final labels, numbered by size, largest first, ties by first
// triangle, as compute_parts does. Returns the number of parts.
int32_t number_parts(std::vector<int32_t>& parts, std::vector<int64_t> size,
                     const std::vector<std::pair<int32_t, int32_t>>& links);

}  // namespace isoform
