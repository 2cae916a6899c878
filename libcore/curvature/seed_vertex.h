// The seed's method (4.28) at one vertex by a short path: the one-ring read
// straight from the ring table, the given normal, the 3 x 3 fit and Theorem
// 4.3, with no copies of the ring or the points.
#pragma once

#include "vertex_fit.h"

namespace isoform {

// fit_vertex(mesh, rings, v, CurvatureMethod::Seed, 0, scratch), bit for bit:
// the vertices whose first fit settles them (a usable normal, three points
// or more, a conditioned system: nearly all) take the short path, the rest
// go through fit_vertex.
VertexFitResult fit_seed_vertex(const Mesh& mesh, const VertexRings& rings, int32_t v, VertexFitScratch& scratch);

// What the curvature's store takes of four vertices' results, side by
// side: entry l of each array is vertex first + l's k1, k2, the x, y, z of
// d1 and d2, and its flags.
struct SeedLanes {
  double k1[4], k2[4];
  double d1[3][4], d2[3][4];
  uint8_t flags[4];
};

// fit_seed_vertex for the vertices first .. first + count - 1 (count 1 to
// 4) into out, bit for bit: the short path's steps for the four side by
// side, one vertex per lane of a vector (lanes4.h), with the same
// operations in the same order in every lane. With lanes given and count 4, where the short path settles all four
// vertices (nearly always), their results are left in lanes instead (as
// out would hold them) and true is returned; otherwise out is written.
bool fit_seed_vertices(const Mesh& mesh, const VertexRings& rings, int32_t first, int count,
                       VertexFitScratch& scratch, VertexFitResult (&out)[4], SeedLanes* lanes = nullptr);

}  // namespace isoform
