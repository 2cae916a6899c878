// Section 3.3 of Hamann (1991): neighbours and parts of a triangulation.
#pragma once

#include "mesh.h"

namespace isoform {

// Fills mesh.neighbours (Algorithm 3.1) in O(n) with a vertex-to-triangle
// table, and mesh.stats: boundary, non-manifold and inconsistently oriented
// edges, degenerate triangles, Euler characteristic. Where three or more
// triangles share an edge none of them is recorded as a neighbour there.
void compute_neighbours(Mesh& mesh);

// Fills mesh.parts and mesh.part_count (Algorithm 3.2, as union-find over
// neighbours): triangles connected across shared edges form one part. Parts
// are numbered by size, largest first; ties by their smallest triangle index.
// Needs mesh.neighbours.
void compute_parts(Mesh& mesh);

// True if triangle t repeats a vertex or has zero area: the cross product of
// its edges, in double from the stored float points, is exactly zero.
bool is_degenerate_triangle(const Mesh& mesh, size_t t);

// Both of the above.
void compute_topology(Mesh& mesh);

}  // namespace isoform
